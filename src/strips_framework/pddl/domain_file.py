"""Reading a PDDL domain file: types, constants, predicates, functions, actions and
derived predicates (see :mod:`.reader` for what is accepted and refused)."""

from __future__ import annotations

from collections.abc import Iterator

from strips_framework.errors import InputError
from strips_framework.pddl.formulas import TRUE, And, Atom, Formula, Parameter
from strips_framework.pddl.reader import TOTAL_COST, Reader, header, integer, sections, show_value
from strips_framework.pddl.sexpr import Node, Source
from strips_framework.pddl.task import (
    Action,
    ConditionalEffect,
    Cost,
    DerivedPredicate,
    Domain,
    Predicate,
)


def read_domain(source: Source) -> Domain:
    top = source.read()
    reader = Reader(source, {"=": 2}, set())
    name = header(reader, top, "domain")
    reader.types = _declared_types(reader, top)
    requirements: tuple[str, ...] = ()
    types: list[tuple[str, str]] = []
    constants: list[Parameter] = []
    predicates: list[Predicate] = []
    functions: list[str] = []
    bodies: list[Node] = []
    for section in sections(reader, top, "domain", once=(":requirements",)):
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
        for atom in action.changed_atoms():
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


def _declared_types(reader: Reader, top: Node) -> frozenset[str]:
    """``object`` and every type the ``(:types ...)`` section names, as a type or as a
    parent (IPC domains often leave a parent such as ``vehicle`` undeclared otherwise)."""
    declared = {"object"}
    for section in top[2:]:
        if isinstance(section, Node) and section and section[0] == ":types":
            for item in reader.typed_list(section, section[1:], variables=False):
                declared.add(item.name)
                declared.update(item.types)
    return frozenset(declared)


def _functions(reader: Reader, section: Node) -> Iterator[str]:
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


def _keyed(reader: Reader, section: Node, keys: tuple[str, ...]) -> dict[str, object]:
    """The ``:key value`` pairs after an action's name, each key at most once (a second
    ``:precondition`` is a mistake, not a replacement)."""
    values: dict[str, object] = {}
    items = section[2:]
    if len(items) % 2:
        raise reader.error(section, f"expected pairs of {', '.join(keys)} and a value")
    for key, value in zip(items[::2], items[1::2], strict=True):
        if key not in keys:
            raise reader.error(
                section, f"expected one of {', '.join(keys)}, found {show_value(key)}"
            )
        if key in values:
            where = value if isinstance(value, Node) else section
            raise reader.error(where, f"{key} is given twice in action {section[1]!r}")
        values[str(key)] = value
    return values


def _action(reader: Reader, section: Node, functions: set[str]) -> Action:
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
    effects = _Effects()
    effect = parts.get(":effect")
    if effect is not None:
        _effect(reader, reader.node(effect, section, "an effect"), variables, functions, effects)
    cost: Cost | None = None
    if effects.costs:
        if len(effects.costs) > 1:
            raise reader.error(section, "expected at most one (increase (total-cost) ...) effect")
        cost = effects.costs[0]
    line, _ = reader.source.position(section.offset)
    return Action(
        name,
        params,
        precondition,
        tuple(effects.add),
        tuple(effects.delete),
        cost,
        line,
        tuple(effects.conditional),
    )


class _Effects:
    """What an action's effect says: the literals of one scope (the unconditional ones at
    the top), and the action-wide costs and conditional effects."""

    def __init__(
        self, costs: list[Cost] | None = None, conditional: list[ConditionalEffect] | None = None
    ) -> None:
        self.add: list[Atom] = []
        self.delete: list[Atom] = []
        self.costs: list[Cost] = [] if costs is None else costs
        self.conditional: list[ConditionalEffect] = [] if conditional is None else conditional


def _effect(
    reader: Reader,
    node: Node,
    variables: frozenset[str],
    functions: set[str],
    into: _Effects,
    params: tuple[Parameter, ...] = (),
    conditions: tuple[Formula, ...] = (),
) -> None:
    """Read ``node`` into ``into``; ``params`` and ``conditions`` are those of the
    enclosing ``forall`` and ``when`` (nested ones accumulate)."""
    head = node[0] if node else None
    if head is None:
        return
    if head == "and":
        for part in node[1:]:
            part_node = reader.node(part, node, "an effect")
            _effect(reader, part_node, variables, functions, into, params, conditions)
    elif head == "not":
        reader.arity(node, 1)
        into.delete.append(reader.atom(reader.node(node[1], node, "an atom"), variables))
    elif head == "increase":
        if params or conditions:
            raise reader.error(
                node, "not supported: action costs inside conditional or universal effects"
            )
        into.costs.append(_cost(reader, node, variables, functions))
    elif head in ("when", "forall"):
        reader.arity(node, 2)
        if head == "when":
            conditions += (reader.formula(node[1], node, variables),)
        else:
            new = tuple(
                reader.typed_list(node, list(reader.node(node[1], node, "a parameter list")), True)
            )
            for param in new:
                if param.name in variables:
                    raise reader.error(
                        node, f"variable {param.name} is already bound in this action"
                    )
            params += new
            variables = variables | {param.name for param in new}
        scope = _Effects(into.costs, into.conditional)
        inner = reader.node(node[2], node, "an effect")
        _effect(reader, inner, variables, functions, scope, params, conditions)
        if scope.add or scope.delete:
            condition = conditions[0] if len(conditions) == 1 else And(conditions)
            into.conditional.append(
                ConditionalEffect(params, condition, tuple(scope.add), tuple(scope.delete))
            )
    elif head in ("decrease", "assign", "scale-up", "scale-down"):
        raise reader.error(node, f"not supported: numeric effect '{head}'")
    else:
        into.add.append(reader.atom(node, variables))


def _cost(reader: Reader, node: Node, variables: frozenset[str], functions: set[str]) -> Cost:
    reader.arity(node, 2)
    target = node[1]
    if not (isinstance(target, Node) and list(target) == [TOTAL_COST]):
        raise reader.error(
            node, "not supported: numeric fluents (only (increase (total-cost) ...))"
        )
    amount = node[2]
    if isinstance(amount, str):
        return integer(reader, amount, node)
    term = reader.node(amount, node, "a number or a function term")
    function = reader.name(term[0] if term else None, term, "a function name")
    if function not in functions or function == TOTAL_COST:
        raise reader.error(term, f"undeclared function {function!r}")
    return Atom(function, tuple(reader.term(arg, term, variables) for arg in term[1:]))


def _derived(reader: Reader, section: Node) -> DerivedPredicate:
    if len(section) != 3:
        raise reader.error(section, "expected '(:derived (predicate ?x ...) formula)'")
    head_node = reader.node(section[1], section, "the derived predicate (name ?x ...)")
    params = tuple(reader.typed_list(head_node, head_node[1:], variables=True))
    variables = frozenset(param.name for param in params)
    as_atom = Node(head_node.offset)
    as_atom.extend([head_node[0] if head_node else None, *(param.name for param in params)])
    head = reader.atom(as_atom, variables)
    return DerivedPredicate(head, params, reader.formula(section[2], section, variables))
