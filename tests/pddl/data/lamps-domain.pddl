; Negative preconditions that decide the order of the plan: a lamp is painted while off,
; and switched on only once the paint is dry.
(define (domain lamps)
  (:requirements :strips :negative-preconditions)
  (:predicates (on ?l) (painted ?l) (dry ?l))
  (:action switch-on :parameters (?l) :precondition (and (not (on ?l)) (dry ?l)) :effect (on ?l))
  (:action switch-off :parameters (?l) :precondition (on ?l) :effect (not (on ?l)))
  (:action paint :parameters (?l) :precondition (not (on ?l))
    :effect (and (painted ?l) (not (dry ?l))))
  (:action wait :parameters (?l) :precondition (not (dry ?l)) :effect (dry ?l)))
