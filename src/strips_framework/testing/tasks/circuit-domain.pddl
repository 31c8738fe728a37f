; Switches between nodes of a circuit; a node is powered (a derived predicate) when a
; closed switch links it to a powered one. Broken switches are repaired only while no
; power reaches them (a negative precondition on a derived predicate).
(define (domain circuit)
  (:requirements :strips :negative-preconditions :derived-predicates
                 :disjunctive-preconditions :existential-preconditions)
  (:predicates (source ?n) (wire ?a ?b) (closed ?a ?b) (broken ?a ?b) (powered ?n))
  (:derived (powered ?n)
    (or (source ?n) (exists (?m) (and (powered ?m) (wire ?m ?n) (closed ?m ?n)))))
  (:action close
    :parameters (?a ?b)
    :precondition (and (wire ?a ?b) (not (closed ?a ?b)) (not (broken ?a ?b)))
    :effect (closed ?a ?b))
  (:action open
    :parameters (?a ?b)
    :precondition (closed ?a ?b)
    :effect (not (closed ?a ?b)))
  (:action repair
    :parameters (?a ?b)
    :precondition (and (broken ?a ?b) (not (powered ?a)))
    :effect (not (broken ?a ?b))))
