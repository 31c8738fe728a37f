(define (problem crates-3) (:domain crates)
  (:objects c1 c2 c3 - crate)
  (:init (heavy c1) (heavy c3))
  (:goal (and (shipped) (forall (?c - crate) (imply (heavy ?c) (loaded ?c))))))
