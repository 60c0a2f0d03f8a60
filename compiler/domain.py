"""Load a domain file: enumerations, constants, object classes, functions, action schemas.

This is the "load and check the shape" step: every key is validated with its position,
every expression is parsed (so a syntax error points into the file), and nothing is
resolved yet; `ground.py` gives names their meaning once a dungeon supplies objects.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import BccError
from . import ast
from .parse import parse_effects, parse_expression
from .source import YList, YMap, check_keys, error_at, error_on, load_yaml, origin, suggest, Origin

DOMAINS_DIR = Path(__file__).resolve().parent.parent / "domains"
BUILTIN_TYPES = ("int", "bool")
SIZE_CONSTANTS = ("width", "height", "depth")
_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


@dataclass(frozen=True)
class Expr:
    """A parsed expression (or effect list) and where its text lives."""
    node: object
    where: Origin
    text: str

    def error(self, message: str, node: ast.Node | None = None) -> BccError:
        line, col = (node or self.node).pos if hasattr(node or self.node, "pos") else (1, 1)
        return self.where.error(message, line, col)


@dataclass
class EnumType:
    name: str
    values: list[str]                     # dense index -> name
    ids: list[int]                        # dense index -> external id
    properties: dict[str, list]           # property -> value per dense index

    def index(self, name: str) -> int:
        return self.values.index(name)


@dataclass
class AttrDef:
    name: str
    type: str
    range: tuple[Expr, Expr] | None = None
    names: dict[str, int] = field(default_factory=dict)
    default: object = None


@dataclass
class ClassDef:
    name: str
    attrs: dict[str, AttrDef]
    key: list[str] = field(default_factory=list)
    position: list[str] = field(default_factory=list)


@dataclass
class Param:
    name: str
    type: str


@dataclass
class FunctionDef:
    name: str
    params: list[Param]
    body: Expr


@dataclass
class ActionDef:
    name: str
    params: list[Param]
    lets: list[tuple[str, Expr]]
    pre: list[Expr]
    effects: Expr
    cost: int = 1


@dataclass
class Domain:
    name: str
    path: str
    description: str
    enums: dict[str, EnumType]
    constants: dict[str, tuple[int, ...]]
    classes: dict[str, ClassDef]
    functions: dict[str, FunctionDef]
    actions: dict[str, ActionDef]
    failure: Expr | None
    binding: YMap                         # the `dungeon:` section, read by dungeon.py
    source: YMap


def resolve_domain_path(ref: str, relative_to: Path | None = None) -> Path:
    """A domain is a shipped name (a file stem in domains/) or a path (relative to the dungeon file)."""
    candidates = []
    if relative_to is not None:
        candidates.append(relative_to.parent / ref)
    candidates += [Path(ref), DOMAINS_DIR / f"{ref}.yaml", DOMAINS_DIR / ref]
    for c in candidates:
        if c.is_file():
            return c
    shipped = [p.stem for p in DOMAINS_DIR.glob("*.yaml")]
    raise BccError(f"unknown domain {ref!r}{suggest(ref, shipped)}; shipped domains: {', '.join(sorted(shipped))}")


def load_domain(path: str | Path) -> Domain:
    data = load_yaml(path)
    check_keys(data, {"domain", "description", "types", "constants", "classes", "dungeon",
                      "functions", "failure", "actions"}, {"domain", "classes", "actions"}, "a domain")
    enums = _load_enums(data.get("types", YMap()) if "types" in data else None)
    constants = _load_constants(data)
    classes = _load_classes(data, enums)
    names_in_use = set(enums) | set(classes) | set(BUILTIN_TYPES)
    if set(enums) & set(classes):
        clash = sorted(set(enums) & set(classes))[0]
        raise error_at(data["classes"], clash, f"{clash!r} is both a type and a class", on_key=True)
    functions = {}
    section = data.get("functions") or YMap()
    for name, fdef in section.items():
        _ident(section, name, name, "a function name")
        if isinstance(fdef, YMap):
            check_keys(fdef, {"params", "body", "description"}, {"body"}, f"function {name!r}")
            functions[name] = FunctionDef(name, _param_list(fdef, names_in_use), _expr(fdef, "body"))
        else:  # `name: expression` is a function without parameters
            functions[name] = FunctionDef(name, [], _expr(section, name))
    actions = {name: _load_action(data["actions"], name, names_in_use) for name in data["actions"]}
    failure = _expr(data, "failure") if "failure" in data else None
    binding = data.get("dungeon", YMap())
    _check_binding(data, binding, classes)
    return Domain(str(data["domain"]), str(path), str(data.get("description", "")).strip(), enums,
                  constants, classes, functions, actions, failure, binding, data)


def _check_binding(data, b, classes) -> None:
    """The `dungeon:` section names classes and attributes; check them all here, with positions."""
    if not isinstance(b, YMap):
        raise error_at(data, "dungeon", "`dungeon` maps parts of a dungeon file (grid, agent, ...) to classes")
    check_keys(b, {"grid", "agent", "agent_fields", "inventory", "rooms"}, set(), "the `dungeon` section")

    def cls(container, key):
        name = container[key]
        if not isinstance(name, str) or name not in classes:
            raise error_at(container, key, f"unknown class {name!r}{suggest(str(name), classes)}")
        return classes[name]

    def attr(container, key, cdef):
        name = container[key]
        if not isinstance(name, str) or name not in cdef.attrs:
            raise error_at(container, key, f"class {cdef.name!r} has no attribute {name!r}{suggest(str(name), cdef.attrs)}")

    for key in ("grid", "agent"):
        if key in b:
            cls(b, key)
    fields = b.get("agent_fields")
    if fields is not None:
        if "agent" not in b or not isinstance(fields, YMap):
            raise error_at(b, "agent_fields", "`agent_fields` maps dungeon keys (facing, looking, selected) to attributes of the agent class")
        check_keys(fields, {"facing", "looking", "selected"}, set(), "`agent_fields`")
        for key in fields:
            attr(fields, key, cls(b, "agent"))
    for part, keys in (("inventory", ("item", "count")), ("rooms", ("fields",))):
        spec = b.get(part)
        if spec is None:
            continue
        if not isinstance(spec, YMap):
            raise error_at(b, part, f"`{part}` needs `class` and {', '.join(keys)}")
        check_keys(spec, {"class", *keys}, {"class", *keys}, f"`dungeon.{part}`")
        cdef = cls(spec, "class")
        if part == "inventory":
            for key in keys:
                attr(spec, key, cdef)
            continue
        rfields = spec["fields"]
        if not isinstance(rfields, YMap):
            raise error_at(spec, "fields", "`fields` maps room keys (x, z, color) to attributes")
        for key, target in rfields.items():
            names = target if isinstance(target, list) else [target]
            for name in names:
                if name not in cdef.attrs:
                    raise error_at(rfields, key, f"class {cdef.name!r} has no attribute {name!r}{suggest(str(name), cdef.attrs)}")


def _expr(container, key, effects: bool = False) -> Expr:
    text = container[key]
    where = origin(container, key)
    if isinstance(text, bool):  # `pre: true` in YAML is a bool, not the text "true"
        text = "true" if text else "false"
    elif isinstance(text, int):
        text = str(text)
    node = parse_effects(text, where) if effects else parse_expression(text, where)
    return Expr(node, where, text)


def _ident(container, key, value, what: str) -> str:
    if not isinstance(value, str) or not _IDENT.match(value):
        raise error_at(container, key, f"{what} must be a name (letters, digits, _), found {value!r}")
    return value


def _load_enums(section) -> dict[str, EnumType]:
    enums = {}
    if section is None:
        return enums
    if not isinstance(section, YMap):
        raise error_on(section, "`types` must map type names to their values")
    for tname, tdef in section.items():
        _ident(section, tname, tname, "a type name")
        if tname in BUILTIN_TYPES:
            raise error_at(section, tname, f"{tname!r} is a built-in type", on_key=True)
        if not isinstance(tdef, YMap):
            raise error_at(section, tname, "a type needs `values` (a list or a mapping)")
        check_keys(tdef, {"values", "properties"}, {"values"}, f"type {tname!r}")
        defaults = dict(tdef.get("properties") or {})
        values = tdef["values"]
        names, ids, props = [], [], {p: [] for p in defaults}
        if isinstance(values, YList):
            items = [(v, YMap()) for v in values]
            for i, v in enumerate(values):
                _ident(values, i, v, "a value")
        elif isinstance(values, YMap):
            items = list(values.items())
        else:
            raise error_at(tdef, "values", "`values` must be a list of names or a mapping")
        for i, (vname, vdef) in enumerate(items):
            if not isinstance(vdef, YMap):
                raise error_at(values, vname, "a value's definition must be a mapping, e.g. {id: 7}")
            check_keys(vdef, {"id"} | set(defaults), set(), f"value {vname!r}")
            if str(vname) in names:
                raise error_at(values, i if isinstance(values, YList) else vname, f"{vname!r} is listed twice in {tname!r}")
            vid = vdef.get("id", i)
            if not isinstance(vid, int) or isinstance(vid, bool):
                raise error_at(vdef, "id", "`id` must be a whole number")
            names.append(str(vname))
            ids.append(vid)
            for p in defaults:
                v = vdef.get(p, defaults[p])
                if type(v) is not type(defaults[p]):
                    raise error_at(vdef, p, f"property {p!r} must be {type(defaults[p]).__name__} like its default")
                props[p].append(v)
        if len(set(ids)) != len(ids):
            raise error_at(tdef, "values", f"type {tname!r} has two values with the same id")
        enums[tname] = EnumType(tname, names, ids, props)
    return enums


def _load_constants(data) -> dict[str, tuple[int, ...]]:
    out = {}
    for name, values in (data.get("constants") or {}).items():
        _ident(data["constants"], name, name, "a constant name")
        if isinstance(values, int) and not isinstance(values, bool):
            values = [values]
        if not isinstance(values, list) or not all(isinstance(v, int) and not isinstance(v, bool) for v in values):
            raise error_at(data["constants"], name, "a constant is an integer or a list of integers")
        out[name] = tuple(values)
    return out


def _load_classes(data, enums) -> dict[str, ClassDef]:
    section = data["classes"]
    if not isinstance(section, YMap):
        raise error_at(data, "classes", "`classes` must map class names to definitions")
    classes = {}
    for cname, cdef in section.items():
        _ident(section, cname, cname, "a class name")
        if not isinstance(cdef, YMap):
            raise error_at(section, cname, "a class needs `attributes`")
        check_keys(cdef, {"attributes", "key", "position", "description"}, {"attributes"}, f"class {cname!r}")
        attrs = {}
        for aname, adef in (cdef["attributes"] or {}).items():
            attrs[aname] = _load_attr(cdef["attributes"], aname, adef, enums)
        for listed in ("key", "position"):
            if listed in cdef and not (isinstance(cdef[listed], YList) and all(isinstance(a, str) for a in cdef[listed])):
                raise error_at(cdef, listed, f"`{listed}` is a list of attribute names, e.g. [x, y, z]")
            for i, a in enumerate(cdef.get(listed) or []):
                if a not in attrs:
                    raise error_at(cdef[listed], i, f"{a!r} is not an attribute of {cname!r}{suggest(str(a), attrs)}")
        classes[cname] = ClassDef(cname, attrs, list(cdef.get("key") or []), list(cdef.get("position") or []))
    return classes


def _load_attr(section, aname, adef, enums) -> AttrDef:
    _ident(section, aname, aname, "an attribute name")
    if isinstance(adef, str):
        adef_map = YMap({"type": adef})
        adef_map.node, adef_map.nodes, adef_map.src = section.node, {"type": section.nodes[aname]}, section.src
        adef = adef_map
    if not isinstance(adef, YMap):
        raise error_at(section, aname, "an attribute is a type name or a mapping with `type`")
    check_keys(adef, {"type", "range", "names", "default", "description"}, {"type"}, f"attribute {aname!r}")
    atype = adef["type"]
    if not isinstance(atype, str):
        raise error_at(adef, "type", "`type` is one type name: int, bool or an enumeration")
    if atype not in BUILTIN_TYPES and atype not in enums:
        raise error_at(adef, "type", f"unknown type {atype!r}{suggest(str(atype), list(enums) + list(BUILTIN_TYPES))}")
    rng = None
    if "range" in adef:
        r = adef["range"]
        if atype != "int" or not isinstance(r, YList) or len(r) != 2:
            raise error_at(adef, "range", "`range` is [low, high] and only for int attributes")
        rng = tuple(_expr(r, i) for i in range(2))
    names = adef.get("names") or YMap()
    if not isinstance(names, YMap) or not all(isinstance(v, int) and not isinstance(v, bool) for v in names.values()):
        raise error_at(adef, "names", "`names` maps value names to numbers, e.g. {north: 2}")
    names = dict(names)
    default = adef.get("default")
    if default is None:
        default = {"int": 0, "bool": False}.get(atype, enums[atype].values[0] if atype in enums else None)
    elif atype in enums and default not in enums[atype].values:
        raise error_at(adef, "default", f"{default!r} is not a value of {atype!r}{suggest(str(default), enums[atype].values)}")
    elif atype == "bool" and not isinstance(default, bool) or atype == "int" and (not isinstance(default, int) or isinstance(default, bool)):
        raise error_at(adef, "default", f"the default of a {atype} attribute must be a {atype}")
    return AttrDef(aname, atype, rng, names, default)


def _param_list(definition: YMap, known_types) -> list[Param]:
    """`params: {a: agent, t: blocktype}`, in order."""
    section = definition.get("params") or YMap()
    if not isinstance(section, YMap):
        raise error_at(definition, "params", "`params` maps parameter names to types, e.g. {a: agent}")
    params = []
    for pname, ptype in section.items():
        if ptype not in known_types:
            raise error_at(section, pname, f"unknown type or class {ptype!r}{suggest(str(ptype), known_types)}")
        params.append(Param(_ident(section, pname, pname, "a parameter"), ptype))
    return params


def _load_action(section, name, known_types) -> ActionDef:
    _ident(section, name, name, "an action name")
    adef = section[name]
    if not isinstance(adef, YMap):
        raise error_at(section, name, "an action needs at least `effect`")
    check_keys(adef, {"params", "let", "pre", "effect", "cost", "description"}, {"effect"}, f"action {name!r}")
    params = _param_list(adef, known_types)
    let_section = adef.get("let") or YMap()
    if not isinstance(let_section, YMap):
        raise error_at(adef, "let", "`let` maps names to expressions, e.g. {tx: a.x + 1}")
    lets = [(_ident(let_section, k, k, "a let name"), _expr(let_section, k)) for k in let_section]
    pre = adef.get("pre")
    if pre is None:
        pres = []
    elif isinstance(pre, YList):
        pres = [_expr(pre, i) for i in range(len(pre))]
    else:
        pres = [_expr(adef, "pre")]
    effect = adef["effect"]
    if isinstance(effect, YList):  # a list of effects is the same as joining them with `;`
        effects = tuple(e for i in range(len(effect)) for e in _expr(effect, i, effects=True).node)
        eff = Expr(effects, origin(adef, "effect"), "; ".join(map(str, effect)))
    else:
        eff = _expr(adef, "effect", effects=True)
    cost = adef.get("cost", 1)
    if not isinstance(cost, int) or isinstance(cost, bool) or cost < 0:
        raise error_at(adef, "cost", "`cost` must be a non-negative integer")
    return ActionDef(name, params, lets, pres, eff, cost)
