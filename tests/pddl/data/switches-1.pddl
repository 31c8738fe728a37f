(define (problem switches-1) (:domain switches)
  (:objects s1 s2 s3 s4 - switch)
  (:init (on s2) (linked s1 s2) (linked s2 s3) (linked s3 s4))
  (:goal (and (all-on) (touched s1))))
