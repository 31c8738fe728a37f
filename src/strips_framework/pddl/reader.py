"""The structural PDDL parser: s-expressions (see :mod:`.sexpr`) to the lifted task.

It is as loose as Fast Downward and pyperplan where IPC files are loose (any case, types
used without ``:typing``, ``object`` implicit, constants repeated as objects, any
requirement flag that changes nothing) and strict where looseness would give wrong plans:
what the planner cannot honour is an error saying ``not supported: ...``. Every error
names the file, the line and column, and what was expected there.
"""

from __future__ import annotations

from collections.abc import Iterator

from strips_framework.errors import InputError
from strips_framework.pddl.formulas import (
    TRUE,
    And,
    Atom,
    Exists,
    Forall,
    Formula,
    Imply,
    Not,
    Or,
    Parameter,
)
from strips_framework.pddl.sexpr import Node, Source
from strips_framework.pddl.task import Action, Cost, DerivedPredicate, Domain, Predicate, Problem

#: Requirements whose features the planner does not have; asking for them is an error.
UNSUPPORTED_REQUIREMENTS = frozenset(
    {
        ":durative-actions",
        ":duration-inequalities",
        ":continuous-effects",
        ":timed-initial-literals",
        ":preferences",
        ":constraints",
        ":time",
    }
)
TOTAL_COST = "total-cost"


class _Reader:
    """Parsing helpers shared by the domain and the problem: they know the source (for
    errors), the declared predicates (for arity checks) and the known objects."""

    def __init__(self, source: Source, predicates: dict[str, int], objects: set[str]) -> None:
        self.source = source
        self.arities = predicates
        self.objects = objects

    def error(self, where: Node | int, message: str) -> Exception:
        return self.source.error(where, message)

    def node(self, value: object, parent: Node, expected: str) -> Node:
        if not isinstance(value, Node):
            raise self.error(parent, f"expected {expected}, found {value!r}")
        return value

    def name(self, value: object, parent: Node, expected: str) -> str:
        if not isinstance(value, str) or value.startswith("?"):
            raise self.error(parent, f"expected {expected}, found {_show(value)}")
        return value

    def requirements(self, node: Node) -> tuple[str, ...]:
        flags = tuple(self.name(flag, node, "a requirement flag") for flag in node[1:])
        for flag in flags:
            if flag in UNSUPPORTED_REQUIREMENTS:
                raise self.error(node, f"not supported: requirement {flag}")
        return flags

    def typed_list(self, node: Node, items: list[object], variables: bool) -> list[Parameter]:
        """``a b - t c - (either t1 t2) d``; names without a type are ``object``."""
        result: list[Parameter] = []
        pending: list[str] = []
        index = 0
        while index < len(items):
            item = items[index]
            if item == "-":
                if index + 1 >= len(items):
                    raise self.error(node, "expected a type after '-'")
                types = self.type_spec(items[index + 1], node)
                result.extend(Parameter(name, types) for name in pending)
                pending = []
                index += 2
                continue
            if not isinstance(item, str) or item.startswith("?") != variables:
                expected = "a variable (?name)" if variables else "a name"
                raise self.error(node, f"expected {expected}, found {_show(item)}")
            pending.append(item)
            index += 1
        result.extend(Parameter(name) for name in pending)
        return result

    def type_spec(self, item: object, parent: Node) -> tuple[str, ...]:
        if isinstance(item, Node):
            if not item or item[0] != "either" or len(item) < 2:
                raise self.error(item, "expected a type name or (either type ...)")
            return tuple(self.name(kind, item, "a type name") for kind in item[1:])
        return (self.name(item, parent, "a type name"),)

    def atom(self, node: Node, variables: frozenset[str]) -> Atom:
        head = node[0] if node else None
        predicate = self.name(head, node, "a predicate name")
        args = tuple(self.term(arg, node, variables) for arg in node[1:])
        arity = self.arities.get(predicate)
        if arity is None:
            raise self.error(node, f"undeclared predicate {predicate!r}")
        if arity != len(args):
            raise self.error(
                node, f"predicate {predicate!r} takes {arity} arguments, found {len(args)}"
            )
        return Atom(predicate, args)

    def term(self, value: object, parent: Node, variables: frozenset[str]) -> str:
        if not isinstance(value, str):
            raise self.error(parent, "expected a variable or an object, found a list")
        if value.startswith("?"):
            if value not in variables:
                raise self.error(parent, f"unknown variable {value}")
        elif value not in self.objects:
            raise self.error(parent, f"unknown object or constant {value!r}")
        return value

    def formula(self, value: object, parent: Node, variables: frozenset[str]) -> Formula:
        node = self.node(value, parent, "a formula in parentheses")
        if not node:
            return TRUE
        head = node[0]
        if head == "and":
            return And(tuple(self.formula(part, node, variables) for part in node[1:]))
        if head == "or":
            return Or(tuple(self.formula(part, node, variables) for part in node[1:]))
        if head == "not":
            self.arity(node, 1)
            return Not(self.formula(node[1], node, variables))
        if head == "imply":
            self.arity(node, 2)
            return Imply(
                self.formula(node[1], node, variables), self.formula(node[2], node, variables)
            )
        if head in ("exists", "forall"):
            self.arity(node, 2)
            params = tuple(
                self.typed_list(node, list(self.node(node[1], node, "a parameter list")), True)
            )
            inner = variables | {param.name for param in params}
            body = self.formula(node[2], node, inner)
            return Exists(params, body) if head == "exists" else Forall(params, body)
        if head == "=":
            self.arity(node, 2)
            return Atom(
                "=", (self.term(node[1], node, variables), self.term(node[2], node, variables))
            )
        if head in ("when", "preference") and head not in self.arities:
            raise self.error(node, f"not supported: '{head}' in a formula")
        if head in ("<", ">", "<=", ">="):
            raise self.error(node, "not supported: numeric conditions")
        return self.atom(node, variables)

    def arity(self, node: Node, count: int) -> None:
        if len(node) != count + 1:
            raise self.error(node, f"expected {count} argument(s) after {node[0]!r}")


def _show(value: object) -> str:
    return "a list" if isinstance(value, Node) else repr(value)


def _sections(reader: _Reader, top: Node, kind: str) -> Iterator[Node]:
    """The ``(:section ...)`` lists after ``(define (kind name) ...)``."""
    for item in top[2:]:
        node = reader.node(item, top, f"a '(:section ...)' of the {kind}")
        if not node or not isinstance(node[0], str) or not node[0].startswith(":"):
            raise reader.error(node, f"expected a '(:section ...)' of the {kind}")
        yield node


def _header(reader: _Reader, top: Node, kind: str) -> str:
    if len(top) < 2 or top[0] != "define":
        raise reader.error(top, f"expected '(define ({kind} NAME) ...)'")
    head = reader.node(top[1], top, f"({kind} NAME)")
    if len(head) != 2 or head[0] != kind:
        raise reader.error(top, f"expected '({kind} NAME)' after 'define'")
    return reader.name(head[1], head, f"the {kind} name")


def read_domain(source: Source) -> Domain:
    top = source.read()
    reader = _Reader(source, {"=": 2}, set())
    name = _header(reader, top, "domain")
    requirements: tuple[str, ...] = ()
    types: list[tuple[str, str]] = []
    constants: list[Parameter] = []
    predicates: list[Predicate] = []
    functions: list[str] = []
    bodies: list[Node] = []
    for section in _sections(reader, top, "domain"):
        key = section[0]
        if key == ":requirements":
            requirements = reader.requirements(section)
        elif key == ":types":
            for item in reader.typed_list(section, section[1:], variables=False):
                types.extend((item.name, parent) for parent in item.types if item.name != "object")
        elif key == ":constants":
            constants.extend(reader.typed_list(section, section[1:], variables=False))
        elif key == ":predicates":
            for item in section[1:]:
                node = reader.node(item, section, "a predicate declaration (name ?x ...)")
                pred = reader.name(node[0] if node else None, node, "a predicate name")
                params = tuple(reader.typed_list(node, node[1:], variables=True))
                predicates.append(Predicate(pred, params))
        elif key == ":functions":
            functions.extend(_functions(reader, section))
        elif key in (":action", ":derived"):
            bodies.append(section)
        elif key == ":durative-action":
            raise reader.error(section, "not supported: durative actions")
        elif key == ":constraints":
            raise reader.error(section, "not supported: constraints")
        else:
            raise reader.error(
                section,
                f"expected :requirements, :types, :constants, :predicates, :functions, "
                f":action or :derived, found {key}",
            )
    reader.arities.update((pred.name, len(pred.params)) for pred in predicates)
    reader.objects.update(const.name for const in constants)
    actions, derived = [], []
    for section in bodies:
        if section[0] == ":action":
            actions.append(_action(reader, section, set(functions)))
        else:
            derived.append(_derived(reader, section))
    heads = {rule.head.predicate for rule in derived}
    for action in actions:
        for atom in (*action.add, *action.delete):
            if atom.predicate in heads:
                raise InputError(
                    source.path,
                    action.line,
                    None,
                    f"action {action.name!r} changes {atom.predicate!r}, a derived predicate "
                    "(derived predicates are computed, never added or deleted)",
                )
    return Domain(
        name,
        requirements,
        tuple(types),
        tuple(constants),
        tuple(predicates),
        tuple(functions),
        tuple(actions),
        tuple(derived),
    )


def _functions(reader: _Reader, section: Node) -> Iterator[str]:
    items = section[1:]
    index = 0
    while index < len(items):
        item = items[index]
        if item == "-":
            if index + 1 >= len(items) or items[index + 1] != "number":
                raise reader.error(section, "not supported: functions of a type other than number")
            index += 2
            continue
        node = reader.node(item, section, "a function declaration (name ?x ...)")
        yield reader.name(node[0] if node else None, node, "a function name")
        index += 1


def _keyed(reader: _Reader, section: Node, keys: tuple[str, ...]) -> dict[str, object]:
    """The ``:key value`` pairs after an action's name."""
    values: dict[str, object] = {}
    items = section[2:]
    if len(items) % 2:
        raise reader.error(section, f"expected pairs of {', '.join(keys)} and a value")
    for key, value in zip(items[::2], items[1::2], strict=True):
        if key not in keys:
            raise reader.error(section, f"expected one of {', '.join(keys)}, found {_show(key)}")
        values[str(key)] = value
    return values


def _action(reader: _Reader, section: Node, functions: set[str]) -> Action:
    if len(section) < 2:
        raise reader.error(section, "expected an action name after ':action'")
    name = reader.name(section[1], section, "an action name")
    parts = _keyed(reader, section, (":parameters", ":precondition", ":effect"))
    params_node = reader.node(
        parts.get(":parameters", Node(section.offset)), section, "a parameter list"
    )
    params = tuple(reader.typed_list(params_node, list(params_node), variables=True))
    variables = frozenset(param.name for param in params)
    pre = parts.get(":precondition")
    precondition = TRUE if pre is None else reader.formula(pre, section, variables)
    add: list[Atom] = []
    delete: list[Atom] = []
    costs: list[Cost] = []
    effect = parts.get(":effect")
    if effect is not None:
        _effect(
            reader,
            reader.node(effect, section, "an effect"),
            variables,
            functions,
            (add, delete, costs),
        )
    cost: Cost | None = None
    if costs:
        if len(costs) > 1:
            raise reader.error(section, "expected at most one (increase (total-cost) ...) effect")
        cost = costs[0]
    line, _ = reader.source.position(section.offset)
    return Action(name, params, precondition, tuple(add), tuple(delete), cost, line)


def _effect(
    reader: _Reader,
    node: Node,
    variables: frozenset[str],
    functions: set[str],
    into: tuple[list[Atom], list[Atom], list[Cost]],
) -> None:
    add, delete, costs = into
    head = node[0] if node else None
    if head is None:
        return
    if head == "and":
        for part in node[1:]:
            _effect(reader, reader.node(part, node, "an effect"), variables, functions, into)
    elif head == "not":
        reader.arity(node, 1)
        delete.append(reader.atom(reader.node(node[1], node, "an atom"), variables))
    elif head == "increase":
        costs.append(_cost(reader, node, variables, functions))
    elif head == "when":
        raise reader.error(node, "not supported: conditional effects (when)")
    elif head == "forall":
        raise reader.error(node, "not supported: universally quantified effects (forall)")
    elif head in ("decrease", "assign", "scale-up", "scale-down"):
        raise reader.error(node, f"not supported: numeric effect '{head}'")
    else:
        add.append(reader.atom(node, variables))


def _cost(reader: _Reader, node: Node, variables: frozenset[str], functions: set[str]) -> Cost:
    reader.arity(node, 2)
    target = node[1]
    if not (isinstance(target, Node) and list(target) == [TOTAL_COST]):
        raise reader.error(
            node, "not supported: numeric fluents (only (increase (total-cost) ...))"
        )
    amount = node[2]
    if isinstance(amount, str):
        return _integer(reader, amount, node)
    term = reader.node(amount, node, "a number or a function term")
    function = reader.name(term[0] if term else None, term, "a function name")
    if function not in functions or function == TOTAL_COST:
        raise reader.error(term, f"undeclared function {function!r}")
    return Atom(function, tuple(reader.term(arg, term, variables) for arg in term[1:]))


def _integer(reader: _Reader, text: str, node: Node) -> int:
    try:
        value = float(text)
    except ValueError:
        raise reader.error(node, f"expected a number, found {text!r}") from None
    if value != int(value) or value < 0:
        raise reader.error(node, f"not supported: action cost {text} (costs are natural numbers)")
    return int(value)


def _derived(reader: _Reader, section: Node) -> DerivedPredicate:
    if len(section) != 3:
        raise reader.error(section, "expected '(:derived (predicate ?x ...) formula)'")
    head_node = reader.node(section[1], section, "the derived predicate (name ?x ...)")
    params = tuple(reader.typed_list(head_node, head_node[1:], variables=True))
    variables = frozenset(param.name for param in params)
    as_atom = Node(head_node.offset)
    as_atom.extend([head_node[0] if head_node else None, *(param.name for param in params)])
    head = reader.atom(as_atom, variables)
    return DerivedPredicate(head, params, reader.formula(section[2], section, variables))


def read_problem(source: Source, domain: Domain) -> Problem:
    top = source.read()
    arities = {"=": 2, **{pred.name: len(pred.params) for pred in domain.predicates}}
    reader = _Reader(source, arities, {const.name for const in domain.constants})
    name = _header(reader, top, "problem")
    domain_name = ""
    objects: list[Parameter] = []
    init_nodes: list[object] = []
    goal: Formula | None = None
    goal_section: Node | None = None
    minimize_cost = False
    for section in _sections(reader, top, "problem"):
        key = section[0]
        if key == ":domain":
            reader.arity(section, 1)
            domain_name = reader.name(section[1], section, "the domain name")
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
    reader: _Reader, top: Node, items: list[object], functions: set[str]
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
            numeric.append((Atom(function, args), _integer(reader, value, node)))
        elif head == "at" and len(node) == 3 and isinstance(node[2], Node):
            raise reader.error(node, "not supported: timed initial literals")
        elif head == "not":
            continue  # closed world: a negated initial fact says nothing new
        else:
            atoms.append(reader.atom(node, frozenset()))
    return tuple(atoms), tuple(numeric)


def _metric(reader: _Reader, section: Node) -> bool:
    if len(section) == 3 and section[1] == "minimize":
        target = section[2]
        if isinstance(target, Node) and list(target) == [TOTAL_COST]:
            return True
    raise reader.error(section, "not supported: metrics other than (:metric minimize (total-cost))")
