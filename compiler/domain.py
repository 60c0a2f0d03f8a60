"""Load a domain file: enumerations, constants, object classes, functions, action schemas.

This is the "load and check the shape" step: every key is validated with its position,
every expression is parsed (so a syntax error points into the file), and nothing is
resolved yet; `ground.py` gives names their meaning once a dungeon supplies objects.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..errors import BccError
from . import ast
from .names import check_name, check_text
from .limits import MAX_REF_LENGTH, shorten
from .source import YList, YMap, check_keys, error_at, error_on, load_yaml, origin, suggest, Origin

DOMAINS_DIR = Path(__file__).resolve().parent.parent / "domains"
BUILTIN_TYPES = ("int", "bool")
SIZE_CONSTANTS = ("width", "height", "depth")


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
    prop_types: dict = field(default_factory=dict)  # property -> "bool" | "int" | an enumeration name
    prop_defaults: dict = field(default_factory=dict)  # property -> its declared default
    # table properties (`per: E`): property -> E; each value's entry is then a dict from E's
    # value names to values (entries left out take the default), read as `v.prop[e]`
    prop_per: dict = field(default_factory=dict)

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
    start: Expr | None = None             # `dungeon.start`, parsed here (a cached domain needs no parser)
    tasks: dict = field(default_factory=dict)     # compound tasks (tasks.py): name -> TaskDef
    methods: dict = field(default_factory=dict)   # their methods, in the file's order: name -> MethodDef


def resolve_domain_path(ref: str, relative_to: Path | None = None) -> Path:
    """A domain is a shipped name (a file stem in domains/) or a path (relative to the dungeon file)."""
    if len(ref) > MAX_REF_LENGTH:
        raise BccError(f"a domain reference is a name or a path of at most {MAX_REF_LENGTH} characters, "
                       f"found {len(ref):,}")
    candidates = []
    if relative_to is not None:
        candidates.append(relative_to.parent / ref)
    candidates += [Path(ref), DOMAINS_DIR / f"{ref}.yaml", DOMAINS_DIR / ref]
    for c in candidates:
        if is_file(c):
            return c
    shipped = [p.stem for p in DOMAINS_DIR.glob("*.yaml")]
    raise BccError(f"unknown domain {shorten(repr(ref))}{suggest(ref, shipped)}; "
                   f"shipped domains: {', '.join(sorted(shipped))}")


def is_file(path: Path) -> bool:
    """Path.is_file, False for names the system refuses (too long, a NUL byte) instead of an OSError."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


DOMAIN_KEYS = {"domain", "description", "extends", "types", "constants", "classes", "dungeon",
               "functions", "failure", "actions", "tasks", "methods"}


def load_domain(path: str | Path, _chain: tuple = ()) -> Domain:
    """Load a domain file. With `extends: other`, start from that domain: add types, enum
    values, constants, classes, functions and actions, or replace one by name when its
    definition says `override: true`. Redefining without `override` is an error."""
    data = load_yaml(path)
    base = None
    if "extends" in data:
        ref = data["extends"]
        if not isinstance(ref, str):
            raise error_at(data, "extends", "`extends` names one domain (a shipped name or a path)")
        try:
            base_path = resolve_domain_path(ref, Path(path))
        except BccError as exc:
            raise error_at(data, "extends", exc.message) from None
        chain = _chain + (Path(path).resolve(),)
        if base_path.resolve() in chain:
            names = " -> ".join(p.stem for p in chain + (base_path.resolve(),))
            raise error_at(data, "extends", f"domains extend each other in a cycle: {names}")
        base = load_domain(base_path, chain)
    check_keys(data, DOMAIN_KEYS, {"domain"} if base else {"domain", "classes", "actions"}, "a domain")
    if data.get("types") is not None and not isinstance(data["types"], YMap):
        raise error_at(data, "types", "`types` must map type names to their values")
    enums = _load_enums(data.get("types"), base.enums if base else {})
    constants = dict(base.constants) if base else {}
    for name, values in _load_constants(data).items():
        if name in constants:
            raise error_at(data["constants"], name, f"constant {name!r} is already defined in {base.name!r}", on_key=True)
        constants[name] = values
    classes = _merge("class", data, "classes", base.classes if base else {},
                     lambda section, name: _load_class(section, name, enums), base)
    if set(enums) & set(classes):
        clash = sorted(set(enums) & set(classes))[0]
        raise error_at(data.get("classes") or data, clash, f"{clash!r} is both a type and a class", on_key=True)
    names_in_use = set(enums) | set(classes) | set(BUILTIN_TYPES)
    functions = _merge("function", data, "functions", base.functions if base else {},
                       lambda section, name: _load_function(section, name, names_in_use), base)
    actions = _merge("action", data, "actions", base.actions if base else {},
                     lambda section, name: _load_action(section, name, names_in_use), base)
    from types import SimpleNamespace
    from .tasks import check_hierarchy, load_methods, load_tasks
    read = SimpleNamespace(merge=_merge, params=_param_list, expr=_expr, ident=_ident, enums=enums, param=Param)
    tasks = load_tasks(data, base, names_in_use, read)
    methods = load_methods(data, base, names_in_use, read)
    check_hierarchy(tasks, methods, actions, functions, data)
    failure = _condition(data, "failure") if "failure" in data else (base.failure if base else None)
    binding = _merge_binding(data, base)
    start = _check_binding(data, binding, classes)
    _ident(data, "domain", data["domain"], "the domain name")
    if "description" in data:
        check_text(data, "description", data["description"], "the description")
    return Domain(str(data["domain"]), str(path), str(data.get("description", "")).strip(), enums,
                  constants, classes, functions, actions, failure, binding, data, start, tasks, methods)


def _merge(what: str, data, key: str, inherited: dict, load, base) -> dict:
    """Definitions of one section: the base's, then this file's (new, or `override: true`)."""
    out = dict(inherited)
    section = data.get(key)
    if section is None:
        return out
    if not isinstance(section, YMap):
        raise error_at(data, key, f"`{key}` must map names to definitions")
    for name in section:
        _ident(section, name, name, f"a {what} name")
        definition = section[name]
        override = isinstance(definition, YMap) and definition.get("override") is True
        if name in inherited and not override:
            raise error_at(section, name, f"{what} {name!r} is already defined in {base.name!r}; "
                                          "add `override: true` to replace it", on_key=True)
        if override and name not in inherited:
            raise error_at(definition, "override", f"nothing to override: {base.name if base else 'no base domain'!r} "
                                                   f"has no {what} {name!r}")
        out[name] = load(section, name)
    return out


def _merge_binding(data, base) -> YMap:
    binding = data.get("dungeon")
    if binding is None:
        return base.binding if base else YMap()
    if base is None or not isinstance(binding, YMap):
        return binding
    merged = YMap(base.binding)
    merged.node, merged.src = binding.node, binding.src
    merged.nodes = {**getattr(base.binding, "nodes", {}), **binding.nodes}
    merged.srcs = {**{k: base.binding.src_of(k) for k in base.binding if hasattr(base.binding, "src")},
                   **{k: binding.src for k in binding}}
    for k, v in binding.items():
        if k == "lists" and isinstance(v, YMap) and isinstance(base.binding.get("lists"), YMap):
            lists = YMap({**base.binding["lists"], **v})
            lists.node, lists.src = v.node, v.src
            lists.nodes = {**base.binding["lists"].nodes, **v.nodes}
            lists.srcs = {**{k2: base.binding["lists"].src_of(k2) for k2 in base.binding["lists"]},
                          **{k2: v.src for k2 in v}}
            merged[k] = lists
        else:
            merged[k] = v
    return merged


def _load_function(section, name, names_in_use) -> FunctionDef:
    fdef = section[name]
    if isinstance(fdef, YMap):
        check_keys(fdef, {"params", "body", "description", "override"}, {"body"}, f"function {name!r}")
        return FunctionDef(name, _param_list(fdef, names_in_use), _expr(fdef, "body"))
    return FunctionDef(name, [], _expr(section, name))  # `name: expression`: no parameters


def _check_binding(data, b, classes) -> Expr | None:
    """The `dungeon:` section names classes and attributes; check them all here, with
    positions. Returns its `start` condition, parsed."""
    if not isinstance(b, YMap):
        raise error_at(data, "dungeon", "`dungeon` maps parts of a dungeon file (grid, agent, ...) to classes")
    check_keys(b, {"grid", "agent", "agent_fields", "inventory", "rooms", "lists", "start"}, set(),
               "the `dungeon` section")
    # a condition every dungeon's start must meet, e.g. the agent's cell is free
    start = _expr(b, "start") if "start" in b else None

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
    parts = [("inventory", b, ("item", "count")), ("rooms", b, ("fields",))]
    lists = b.get("lists")
    if lists is not None:
        if not isinstance(lists, YMap):
            raise error_at(b, "lists", "`lists` maps dungeon keys to {class, fields}: lists of named objects")
        parts += [(name, lists, ("fields",)) for name in lists]
    for part, container, keys in parts:
        spec = container.get(part)
        if spec is None:
            continue
        if not isinstance(spec, YMap):
            raise error_at(container, part, f"`{part}` needs `class` and {', '.join(keys)}")
        check_keys(spec, {"class", "required", *keys}, {"class", *keys}, f"`dungeon.{part}`")
        cdef = cls(spec, "class")
        if part == "inventory":
            for key in keys:
                attr(spec, key, cdef)
            continue
        rfields = spec["fields"]
        if not isinstance(rfields, YMap):
            raise error_at(spec, "fields", "`fields` maps room keys (x, z, color) to attributes")
        for key, target in rfields.items():
            _ident(rfields, key, key, "a field name")
            names = target if isinstance(target, list) else [target]
            if not names or not all(isinstance(n, str) for n in names):
                raise error_at(rfields, key, "a field fills one attribute (a name) or several (a list of names)")
            for name in names:
                if name not in cdef.attrs:
                    raise error_at(rfields, key, f"class {cdef.name!r} has no attribute {name!r}{suggest(str(name), cdef.attrs)}")
        required = spec.get("required", [])
        if not isinstance(required, YList) and "required" in spec:
            raise error_at(spec, "required", "`required` is a list of field names, e.g. [species, at]")
        for i, name in enumerate(required):
            if not isinstance(name, str) or name not in rfields:
                raise error_at(required, i, f"`required` lists fields of `dungeon.{part}`; {shorten(repr(name))} "
                                            f"is not one{suggest(str(name), rfields)}")
    return start


def _expr(container, key, effects: bool = False) -> Expr:
    text = _scalar_text(container, key)   # `pre: true` in YAML is a bool, not the text "true"
    where = origin(container, key)
    from .parse import parse_effects, parse_expression   # lark: imported only when text is parsed
    node = parse_effects(text, where) if effects else parse_expression(text, where)
    return Expr(node, where, text)


def _condition(container, key) -> Expr:
    """A condition (a goal, a failure) written as one expression or, as `pre` may be, as a
    list of expressions that must all hold."""
    if not isinstance(container[key], YList):
        return _expr(container, key)
    return _joined(container, key, " and ", effects=False)


def _joined(container, key, separator: str, effects: bool) -> Expr:
    """A YAML list of expressions (each in parentheses, for conditions) or of effects, parsed
    as one text joined by `separator`, whose every character keeps its place in the file:
    an error in the third item points into the third item."""
    items = container[key]
    if not items:
        raise error_at(container, key, f"`{key}` is an empty list: leave the key out instead")
    text, positions, parts = "", [], []
    for i in range(len(items)):
        part = _scalar_text(items, i)
        where = origin(items, i)
        parts.append((part, where))
        start = where.locate(1, 1)
        if i:
            text += separator
            positions += [start] * len(separator)
        opening, closing = ("", "") if effects else ("(", ")")
        text += opening + part + closing
        positions += [start] * len(opening)
        line, col = 1, 1
        for ch in part:
            positions.append(where.locate(line, col))
            line, col = (line + 1, 1) if ch == "\n" else (line, col + 1)
        positions += [where.locate(line, col)] * len(closing)
    from .parse import parse_effects, parse_expression   # lark: imported only when text is parsed
    parse = parse_effects if effects else parse_expression
    first = origin(container, key)
    combined = Origin(first.path, first.line, first.col, 1, tuple(positions), text)
    try:
        node = parse(text, combined)
    except BccError:
        for part, where in parts:   # report the error as in the first bad item alone, not the joining's
            parse(part, where)
        raise
    return Expr(node, combined, text)


def _scalar_text(container, key) -> str:
    """An expression's text as YAML gave it (`pre: true` is a bool, `cost: 1` an int); a
    list or a mapping where an expression belongs is bad input."""
    value = container[key]
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if not isinstance(value, str):
        kind = ("a list" if isinstance(value, YList) else "a mapping" if isinstance(value, YMap)
                else "nothing" if value is None else f"the number {value!r}" if isinstance(value, float)
                else f"a {type(value).__name__}")
        raise error_at(container, key, f"expected an expression as text, found {kind}")
    return value


def _ident(container, key, value, what: str) -> str:
    return check_name(container, key, value, what)


def _load_enums(section, inherited: dict) -> dict[str, EnumType]:
    """Enumerations; a type the base domain has already gets the new values appended."""
    enums = {name: EnumType(e.name, list(e.values), list(e.ids), {p: list(v) for p, v in e.properties.items()},
                            dict(e.prop_types), dict(e.prop_defaults), dict(e.prop_per))
             for name, e in inherited.items()}
    if section is None:
        return enums
    if not isinstance(section, YMap):
        raise error_on(section, "`types` must map type names to their values")
    for tname in section:  # declare every name first: properties may be of another new type
        _ident(section, tname, tname, "a type name")
        if tname in BUILTIN_TYPES:
            raise error_at(section, tname, f"{tname!r} is a built-in type", on_key=True)
        if tname not in enums:
            enums[tname] = EnumType(tname, [], [], {}, {}, {})
    pending = []
    for tname, tdef in section.items():
        if not isinstance(tdef, YMap):
            raise error_at(section, tname, "a type needs `values` (a list or a mapping)")
        check_keys(tdef, {"values", "properties"}, {"values"}, f"type {tname!r}")
        enum = enums[tname]
        inherited_values = set(inherited[tname].values) if tname in inherited else set()
        props = tdef.get("properties") or YMap()
        if not isinstance(props, YMap):
            raise error_at(tdef, "properties", "`properties` maps property names to defaults")
        defaults = {}
        for p, d in props.items():
            _ident(props, p, p, "a property name")
            if p in enum.properties:
                raise error_at(props, p, f"type {tname!r} already has the property {p!r}", on_key=True)
            if isinstance(d, YMap):  # {type: T, default: value}, and with `per: E` a table
                check_keys(d, {"type", "default", "per"}, {"type", "default"}, f"property {p!r}")
                known = list(enums) + list(BUILTIN_TYPES)
                if not isinstance(d["type"], str) or d["type"] not in known:
                    raise error_at(d, "type", f"unknown type {d['type']!r}{suggest(str(d['type']), known)}")
                if "per" in d:
                    if not isinstance(d["per"], str) or d["per"] not in enums:
                        raise error_at(d, "per", f"`per` names the enumeration that indexes the table; "
                                                 f"unknown type {d['per']!r}{suggest(str(d['per']), enums)}")
                    enum.prop_per[p] = d["per"]
                enum.prop_types[p] = d["type"]
                defaults[p] = d["default"]
                pending.append((enum, p, d["default"], d, "default", False))
            elif isinstance(d, (bool, int)):
                enum.prop_types[p] = "bool" if isinstance(d, bool) else "int"
                defaults[p] = d
            else:
                raise error_at(props, p, "a property default is true/false, a number, or {type: T, default: V}")
            enum.properties[p] = [{} if p in enum.prop_per else defaults[p]] * len(enum.values)
            enum.prop_defaults[p] = defaults[p]
        values = tdef["values"]
        if isinstance(values, YList):
            items = [(v, YMap()) for v in values]
            for i, v in enumerate(values):
                _ident(values, i, v, "a value")
        elif isinstance(values, YMap):
            items = list(values.items())
        else:
            raise error_at(tdef, "values", "`values` must be a list of names or a mapping")
        for i, (vname, vdef) in enumerate(items):
            where = (values, i if isinstance(values, YList) else vname)
            if not isinstance(vdef, YMap):
                raise error_at(*where, "a value's definition must be a mapping, e.g. {id: 7}")
            check_keys(vdef, {"id"} | set(enum.properties), set(), f"value {vname!r}")
            if str(vname) in inherited_values:   # a base's value, listed again to set its properties
                if "id" in vdef:
                    raise error_at(vdef, "id", f"{vname!r} is listed twice in {tname!r}: it is the base domain's "
                                               "value, whose id stays; an extending domain may set its properties "
                                               "only", on_key=True)
                inherited_values.discard(str(vname))   # set once
                index = enum.values.index(str(vname))
                for p in vdef:
                    enum.properties[p][index] = _property_value(enum, p, vdef, defaults, pending)
                continue
            if str(vname) in enum.values:
                raise error_at(*where, f"{vname!r} is listed twice in {tname!r}")
            vid = vdef.get("id", len(enum.values))
            if not isinstance(vid, int) or isinstance(vid, bool):
                raise error_at(vdef, "id", "`id` must be a whole number")
            if vid in enum.ids:
                raise error_at(*where, f"type {tname!r} has two values with the id {vid}")
            enum.values.append(str(vname))
            enum.ids.append(vid)
            for p in enum.properties:
                enum.properties[p].append(_property_value(enum, p, vdef, defaults, pending))
    for enum, p, v, where, key, entry in pending:  # check property values once every type is complete
        per = enum.prop_per.get(p)
        if entry and key not in enums[per].values:
            raise error_at(where, key, f"{shorten(repr(key))} is not a value of {per!r}, which indexes the table "
                                       f"{enum.name}.{p}{suggest(str(key), enums[per].values)}", on_key=True)
        _check_property_value(enums, enum, p, v, where, key)
    for enum in enums.values():  # enum-valued properties are stored as dense indices
        for p, ptype in enum.prop_types.items():
            if ptype not in enums:
                continue
            dense = lambda v: v if isinstance(v, int) else enums[ptype].index(v)
            if p in enum.prop_per:
                enum.properties[p] = [{k: dense(v) for k, v in row.items()} for row in enum.properties[p]]
                if not isinstance(enum.prop_defaults[p], int):
                    enum.prop_defaults[p] = dense(enum.prop_defaults[p])
            else:
                enum.properties[p] = [dense(v) for v in enum.properties[p]]
    return enums


def _property_value(enum: EnumType, p: str, vdef, defaults: dict, pending: list):
    """Property `p` of a value defined by `vdef` (a table's entries as a dict), noted in
    `pending` to be checked once every type is complete."""
    if p in enum.prop_per:   # a table: {index value: entry}
        entries = vdef.get(p, YMap())
        if not isinstance(entries, YMap):
            raise error_at(vdef, p, f"property {p!r} is a table: a mapping from values of "
                                    f"{enum.prop_per[p]!r} to {enum.prop_types[p]}, e.g. {{name: 1}}")
        for key in entries:
            pending.append((enum, p, entries[key], entries, key, True))
        return dict(entries)
    v = vdef.get(p, defaults[p] if p in defaults else enum.prop_defaults.get(p))
    pending.append((enum, p, v, vdef if p in vdef else None, p, False))
    return v


def _check_property_value(enums, enum: EnumType, p: str, v, where, key) -> None:
    """A property's value (or a table entry, or a declared default) is of its type."""
    ptype = enum.prop_types[p]
    ok = v in enums[ptype].values if ptype in enums else \
        (isinstance(v, bool) if ptype == "bool" else isinstance(v, int) and not isinstance(v, bool))
    if ok:
        return
    shown = {"int": "an int", "bool": "a bool"}.get(ptype, f"a value of {ptype!r}")
    if where is None:
        raise BccError(f"property {p!r} of {enum.name!r} must be {shown}")
    raise error_at(where, key, f"property {p!r} must be {shown}, found {shorten(repr(v))}"
                               f"{suggest(str(v), enums[ptype].values) if ptype in enums else ''}")


def table_row(enums: dict, enum: EnumType, p: str, index: int) -> tuple:
    """Entry `index` of the table property `p`, as a tuple over the values of its `per`
    enumeration in order (values a table leaves out, or added by a later domain, take the
    property's default)."""
    row, default = enum.properties[p][index], enum.prop_defaults[p]
    return tuple(row.get(name, default) for name in enums[enum.prop_per[p]].values)


def _load_constants(data) -> dict[str, tuple[int, ...]]:
    out = {}
    section = data.get("constants")
    if section is not None and not isinstance(section, YMap):
        raise error_at(data, "constants", "`constants` maps names to an integer or a list of integers")
    for name, values in (section or {}).items():
        _ident(data["constants"], name, name, "a constant name")
        if isinstance(values, int) and not isinstance(values, bool):
            values = [values]
        if not isinstance(values, list) or not all(isinstance(v, int) and not isinstance(v, bool) for v in values):
            raise error_at(data["constants"], name, "a constant is an integer or a list of integers")
        out[name] = tuple(values)
    return out


def _load_class(section, cname, enums) -> ClassDef:
    cdef = section[cname]
    if not isinstance(cdef, YMap):
        raise error_at(section, cname, "a class needs `attributes`")
    check_keys(cdef, {"attributes", "key", "position", "description", "override"}, {"attributes"}, f"class {cname!r}")
    if not isinstance(cdef["attributes"], YMap):
        raise error_at(cdef, "attributes", "`attributes` maps attribute names to types")
    attrs = {}
    for aname, adef in cdef["attributes"].items():
        attrs[aname] = _load_attr(cdef["attributes"], aname, adef, enums)
    for listed in ("key", "position"):
        if listed in cdef and not (isinstance(cdef[listed], YList) and all(isinstance(a, str) for a in cdef[listed])):
            raise error_at(cdef, listed, f"`{listed}` is a list of attribute names, e.g. [x, y, z]")
        for i, a in enumerate(cdef.get(listed) or []):
            if a not in attrs:
                raise error_at(cdef[listed], i, f"{a!r} is not an attribute of {cname!r}{suggest(str(a), attrs)}")
    return ClassDef(cname, attrs, list(cdef.get("key") or []), list(cdef.get("position") or []))


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
    for vname in names:
        _ident(names, vname, vname, "a value name")
    names = dict(names)
    default = adef.get("default")
    if atype in enums and not enums[atype].values:
        raise error_at(adef, "type", f"the type {atype!r} has no values, so no attribute can have it")
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
        if not isinstance(ptype, str) or ptype not in known_types:
            raise error_at(section, pname, f"unknown type or class {ptype!r}{suggest(str(ptype), known_types)}")
        params.append(Param(_ident(section, pname, pname, "a parameter"), ptype))
    return params


def _load_action(section, name, known_types) -> ActionDef:
    _ident(section, name, name, "an action name")
    adef = section[name]
    if not isinstance(adef, YMap):
        raise error_at(section, name, "an action needs at least `effect`")
    check_keys(adef, {"params", "let", "pre", "effect", "cost", "description", "override"}, {"effect"}, f"action {name!r}")
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
        eff = _joined(adef, "effect", ";\n", effects=True)
    else:
        eff = _expr(adef, "effect", effects=True)
    cost = adef.get("cost", 1)
    if not isinstance(cost, int) or isinstance(cost, bool) or cost < 0:
        raise error_at(adef, "cost", "`cost` must be a non-negative integer")
    return ActionDef(name, params, lets, pres, eff, cost)
