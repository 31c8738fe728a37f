; A miconic-style elevator whose stop boards and serves every passenger at once, by
; universal conditional effects (conditions read in the state before the stop).
(define (domain elevator)
  (:requirements :typing :adl)
  (:types passenger floor)
  (:predicates (origin ?p - passenger ?f - floor) (destin ?p - passenger ?f - floor)
               (above ?f1 ?f2 - floor) (lift-at ?f - floor)
               (boarded ?p - passenger) (served ?p - passenger) (vip ?p - passenger))
  (:action up
    :parameters (?f1 ?f2 - floor)
    :precondition (and (lift-at ?f1) (above ?f1 ?f2))
    :effect (and (lift-at ?f2) (not (lift-at ?f1))))
  (:action down
    :parameters (?f1 ?f2 - floor)
    :precondition (and (lift-at ?f1) (above ?f2 ?f1))
    :effect (and (lift-at ?f2) (not (lift-at ?f1))))
  (:action stop
    :parameters (?f - floor)
    :precondition (and (lift-at ?f)
                       ; a VIP on board is never kept waiting at another floor
                       (forall (?p - passenger)
                         (imply (and (vip ?p) (boarded ?p)) (destin ?p ?f))))
    :effect (forall (?p - passenger)
              (and (when (and (boarded ?p) (destin ?p ?f))
                         (and (not (boarded ?p)) (served ?p)))
                   (when (and (origin ?p ?f) (not (served ?p)) (not (boarded ?p)))
                         (boarded ?p))))))
