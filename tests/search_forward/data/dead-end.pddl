; No door leads back into a, and none leads to d: unsolvable.
(define (problem dead-end)
  (:domain corridors)
  (:objects a b c d - room)
  (:init (at a) (door a b) (door b c) (door c b)
         (= (length a b) 1) (= (length b c) 1) (= (length c b) 1) (= (total-cost) 0))
  (:goal (at d))
  (:metric minimize (total-cost)))
