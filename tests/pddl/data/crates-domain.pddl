; Universal conditions whose bodies branch: expanding them would give 2^n clauses for n
; crates, so grounding replaces each by the negation of an auxiliary derived predicate.
(define (domain crates)
  (:requirements :adl)
  (:types crate)
  (:predicates (heavy ?c - crate) (loaded ?c - crate) (sealed ?c - crate) (shipped))
  (:action load :parameters (?c - crate) :precondition (not (loaded ?c)) :effect (loaded ?c))
  (:action seal :parameters (?c - crate) :precondition (loaded ?c) :effect (sealed ?c))
  (:action ship
    :parameters ()
    :precondition (forall (?c - crate) (or (not (loaded ?c)) (sealed ?c)))
    :effect (shipped)))
