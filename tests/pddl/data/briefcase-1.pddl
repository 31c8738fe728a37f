; Pednault's briefcase world: carry the paycheck to the office and the dictionary to
; the bank, and bring the briefcase back home.
(define (problem briefcase-1) (:domain briefcase)
  (:objects home office bank - location p d - portable)
  (:init (is-at home) (at p home) (at d home))
  (:goal (and (is-at home) (at p office) (at d bank))))
