; Parcel p goes from a to d, parcel q from c to b. The direct road a-d costs 10 and the
; way round by b and c 6: the cheapest plan costs 14 in 9 steps, the shortest costs 18.
(define (problem delivery-2) (:domain delivery)
  (:objects a b c d - city p q - parcel)
  (:init (truck-at a) (at p a) (at q c)
         (road a d) (road d a) (road a b) (road b a) (road b c) (road c b) (road c d) (road d c)
         (= (length a d) 10) (= (length d a) 10) (= (length a b) 2) (= (length b a) 2)
         (= (length b c) 2) (= (length c b) 2) (= (length c d) 2) (= (length d c) 2)
         (= (total-cost) 0))
  (:goal (and (at p d) (at q b)))
  (:metric minimize (total-cost)))
