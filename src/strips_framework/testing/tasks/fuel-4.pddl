; From t0 to t3 (three drives) with fuel for 4 drives; a side road leads from t1 to t4.
; One drive to spare: going to t4 and back leaves the car stranded (optimum 3).
(define (problem fuel-4) (:domain fuel)
  (:objects t0 t1 t2 t3 t4 - town f0 f1 f2 f3 f4 - level)
  (:init (at t0) (fuel f4) (next f0 f1) (next f1 f2) (next f2 f3) (next f3 f4)
         (road t0 t1) (road t1 t0) (road t1 t2) (road t2 t1) (road t2 t3) (road t3 t2)
         (road t1 t4) (road t4 t1))
  (:goal (at t3)))
