(define (problem briefcase-2) (:domain briefcase)
  (:objects home office bank shop - location p d b k - portable)
  (:init (is-at home) (at p home) (at d office) (at b bank) (at k shop))
  (:goal (and (is-at home) (at p bank) (at d shop) (at b home) (at k office))))
