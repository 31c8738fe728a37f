; Toggles: which of two conditional effects fires depends on the state before the
; action, and an unconditional add wins over a conditional delete of the same atom.
(define (domain switches)
  (:requirements :adl :derived-predicates)
  (:types switch)
  (:predicates (on ?s - switch) (linked ?s ?t - switch) (touched ?s - switch)
               (all-on))
  (:derived (all-on) (forall (?s - switch) (on ?s)))
  (:action toggle
    :parameters (?s - switch)
    :precondition (not (all-on))
    :effect (and (touched ?s)
                 (when (on ?s) (not (on ?s)))
                 (when (not (on ?s)) (on ?s))
                 (forall (?t - switch)
                   (when (and (linked ?s ?t) (on ?t)) (and (not (on ?t)) (not (touched ?s)))))))
  (:action reset
    :parameters ()
    :effect (forall (?s - switch) (and (not (on ?s)) (not (touched ?s))))))
