; A goal that is no conjunction of atoms: it becomes the derived fact (@goal), and it
; negates the derived predicate reachable (so the goal axiom sits in a higher stratum).
(define (problem rooms-2)
  (:domain rooms)
  (:objects hall1 - hall r1 r2 - room k1 - key)
  (:init (at hall1)
         (door hall1 r1) (door r1 hall1) (door hall1 r2) (door r2 hall1)
         (locked hall1 r2) (locked r2 hall1)
         (key-at k1 r1) (fits k1 hall1 r2)
         (= (length hall1 r1) 3) (= (length r1 hall1) 3)
         (= (length hall1 r2) 5) (= (length r2 hall1) 5))
  (:goal (and (exists (?r - room) (cleaned ?r))
              (or (has k1) (not (reachable r1)))
              (forall (?r - room) (imply (cleaned ?r) (visited ?r))))))
