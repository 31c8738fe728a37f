(define (problem lamps-1) (:domain lamps)
  (:objects a b)
  (:init (on a) (dry a) (dry b))
  (:goal (and (painted a) (on a) (not (on b)))))
