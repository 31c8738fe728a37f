; The direct door costs 10; the detour through b and c costs 3.
(define (problem detour)
  (:domain corridors)
  (:objects a b c d - room)
  (:init (at a) (door a d) (door a b) (door b c) (door c d)
         (= (length a d) 10) (= (length a b) 1) (= (length b c) 1) (= (length c d) 1)
         (= (total-cost) 0))
  (:goal (at d))
  (:metric minimize (total-cost)))
