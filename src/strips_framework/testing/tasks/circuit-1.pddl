; Light the lamp and not the bell: the switch to the lamp must be repaired with x dark
; (optimum 5 steps).
(define (problem circuit-1) (:domain circuit)
  (:objects s x y lamp bell)
  (:init (source s) (wire s x) (wire x lamp) (wire s y) (wire y bell)
         (closed s x) (closed s y) (closed y bell) (broken x lamp))
  (:goal (and (powered lamp) (not (powered bell)))))
