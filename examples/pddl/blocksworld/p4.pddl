; Reverse a tower of four blocks: d c b a (a on top) becomes a b c d (d on top).
(define (problem reverse-four)
  (:domain blocksworld)
  (:objects a b c d - block)
  (:init (clear a) (on a b) (on b c) (on c d) (ontable d) (handempty))
  (:goal (and (on d c) (on c b) (on b a))))
