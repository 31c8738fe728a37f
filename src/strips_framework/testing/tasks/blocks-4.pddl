; A tower to rebuild: c is on a; the goal stacks a on b on c on d (optimum 6 steps).
(define (problem blocks-4) (:domain blocks)
  (:objects a b c d - block)
  (:init (on c a) (ontable a) (ontable b) (ontable d) (clear c) (clear b) (clear d) (handempty))
  (:goal (and (on a b) (on b c) (on c d))))
