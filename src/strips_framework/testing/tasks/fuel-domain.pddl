; A car on a line of towns with a tank that cannot be refilled: every detour burns fuel
; the rest of the way needs, so most reachable states are dead ends.
(define (domain fuel)
  (:requirements :strips :typing)
  (:types town level)
  (:predicates (at ?t - town) (road ?a ?b - town) (fuel ?l - level) (next ?less ?more - level))
  (:action drive
    :parameters (?from ?to - town ?have ?left - level)
    :precondition (and (at ?from) (road ?from ?to) (fuel ?have) (next ?left ?have))
    :effect (and (not (at ?from)) (at ?to) (not (fuel ?have)) (fuel ?left))))
