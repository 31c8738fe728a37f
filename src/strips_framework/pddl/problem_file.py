"""Reading a PDDL problem file against its domain: objects, initial facts and function
values, goal and metric."""

from __future__ import annotations

import warnings

from strips_framework.pddl.formulas import Atom, Formula, Parameter
from strips_framework.pddl.reader import TOTAL_COST, Reader, header, integer, sections
from strips_framework.pddl.sexpr import Node, Source
from strips_framework.pddl.task import Domain, Problem


def read_problem(source: Source, domain: Domain) -> Problem:
    top = source.read()
    arities = {"=": 2, **{pred.name: len(pred.params) for pred in domain.predicates}}
    types = frozenset({"object", *(kind for pair in domain.types for kind in pair)})
    reader = Reader(source, arities, {const.name for const in domain.constants}, types)
    name = header(reader, top, "problem")
    domain_name = ""
    objects: list[Parameter] = []
    init_nodes: list[object] = []
    goal: Formula | None = None
    goal_section: Node | None = None
    minimize_cost = False
    for section in sections(reader, top, "problem", once=(":domain", ":goal", ":metric")):
        key = section[0]
        if key == ":domain":
            reader.arity(section, 1)
            domain_name = reader.name(section[1], section, "the domain name")
            if domain_name != domain.name:
                line, column = source.position(section.offset)
                warnings.warn(
                    f"{source.path}:{line}:{column}: the problem names domain {domain_name!r}, "
                    f"but the domain file defines {domain.name!r}",
                    stacklevel=2,
                )
        elif key == ":requirements":
            reader.requirements(section)
        elif key == ":objects":
            objects.extend(reader.typed_list(section, section[1:], variables=False))
        elif key == ":init":
            init_nodes.extend(section[1:])
        elif key == ":goal":
            reader.arity(section, 1)
            goal_section = section
        elif key == ":metric":
            minimize_cost = _metric(reader, section)
        elif key == ":constraints":
            raise reader.error(section, "not supported: constraints")
        else:
            raise reader.error(
                section,
                f"expected :domain, :requirements, :objects, :init, :goal or :metric, found {key}",
            )
    reader.objects.update(obj.name for obj in objects)
    init, numeric = _init(reader, top, init_nodes, set(domain.functions))
    if goal_section is None:
        raise reader.error(top, "expected a (:goal ...) section")
    goal = reader.formula(goal_section[1], goal_section, frozenset())
    constants = {const.name for const in domain.constants}
    unique = tuple(obj for obj in objects if obj.name not in constants)
    return Problem(name, domain_name, unique, init, numeric, goal, minimize_cost)


def _init(
    reader: Reader, top: Node, items: list[object], functions: set[str]
) -> tuple[tuple[Atom, ...], tuple[tuple[Atom, int], ...]]:
    atoms: list[Atom] = []
    numeric: list[tuple[Atom, int]] = []
    for item in items:
        node = reader.node(item, top, "an initial fact in parentheses")
        head = node[0] if node else None
        if head == "=" and len(node) == 3 and isinstance(node[1], Node):
            term = node[1]
            function = reader.name(term[0] if term else None, term, "a function name")
            if function not in functions:
                raise reader.error(term, f"undeclared function {function!r}")
            value = node[2]
            if not isinstance(value, str):
                raise reader.error(node, "expected a number")
            args = tuple(reader.term(arg, term, frozenset()) for arg in term[1:])
            numeric.append((Atom(function, args), integer(reader, value, node)))
        elif head == "at" and len(node) == 3 and isinstance(node[2], Node):
            raise reader.error(node, "not supported: timed initial literals")
        elif head == "not":
            continue  # closed world: a negated initial fact says nothing new
        else:
            atoms.append(reader.atom(node, frozenset()))
    return tuple(atoms), tuple(numeric)


def _metric(reader: Reader, section: Node) -> bool:
    if len(section) == 3 and section[1] == "minimize":
        target = section[2]
        if isinstance(target, Node) and list(target) == [TOTAL_COST]:
            return True
    raise reader.error(section, "not supported: metrics other than (:metric minimize (total-cost))")
