"""Load a domain file: enumerations, constants, object classes, functions, action schemas.

This is the "load and check the shape" step: every key is validated with its position,
every expression is parsed (so a syntax error points into the file), and nothing is
resolved yet; `ground.py` gives names their meaning once a dungeon supplies objects.
What is loaded is in definitions.py; the `types:` section is read by domain_enums.py,
expressions by domain_exprs.py; this module reads the rest and merges `extends`.
"""
from __future__ import annotations

from pathlib import Path

from ..errors import BccError
from .definitions import BUILTIN_TYPES, ActionDef, AttrDef, ClassDef, Domain, Expr, FunctionDef, Param
from .domain_enums import load_enums
from .domain_exprs import condition, expression, joined
from .names import check_name, check_text
from .limits import MAX_REF_LENGTH, shorten
from .source import YList, YMap, check_keys, error_at, load_yaml, suggest

DOMAINS_DIR = Path(__file__).resolve().parent.parent / "domains"
SIZE_CONSTANTS = ("width", "height", "depth")


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
        from .cache import load_cached
        # the base through the cache, as a dungeon reads its domain: a new or edited domain
        # on a shipped one skips the base chain's YAML and lark
        base = load_cached(base_path, lambda p: load_domain(p, chain), kind="domains")
    check_keys(data, DOMAIN_KEYS, {"domain"} if base else {"domain", "classes", "actions"}, "a domain")
    if data.get("types") is not None and not isinstance(data["types"], YMap):
        raise error_at(data, "types", "`types` must map type names to their values")
    enums = load_enums(data.get("types"), base.enums if base else {})
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
    read = SimpleNamespace(merge=_merge, params=_param_list, expr=expression, ident=_ident, enums=enums, param=Param)
    tasks = load_tasks(data, base, names_in_use, read)
    methods = load_methods(data, base, names_in_use, read)
    check_hierarchy(tasks, methods, actions, functions, data)
    failure = condition(data, "failure") if "failure" in data else (base.failure if base else None)
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
        return FunctionDef(name, _param_list(fdef, names_in_use), expression(fdef, "body"))
    return FunctionDef(name, [], expression(section, name))  # `name: expression`: no parameters


def _check_binding(data, b, classes) -> Expr | None:
    """The `dungeon:` section names classes and attributes; check them all here, with
    positions. Returns its `start` condition, parsed."""
    if not isinstance(b, YMap):
        raise error_at(data, "dungeon", "`dungeon` maps parts of a dungeon file (grid, agent, ...) to classes")
    check_keys(b, {"grid", "agent", "agent_fields", "inventory", "rooms", "lists", "start"}, set(),
               "the `dungeon` section")
    # a condition every dungeon's start must meet, e.g. the agent's cell is free
    start = expression(b, "start") if "start" in b else None

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


def _ident(container, key, value, what: str) -> str:
    return check_name(container, key, value, what)


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
        rng = tuple(expression(r, i) for i in range(2))
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
    lets = [(_ident(let_section, k, k, "a let name"), expression(let_section, k)) for k in let_section]
    pre = adef.get("pre")
    if pre is None:
        pres = []
    elif isinstance(pre, YList):
        pres = [expression(pre, i) for i in range(len(pre))]
    else:
        pres = [expression(adef, "pre")]
    effect = adef["effect"]
    if isinstance(effect, YList):  # a list of effects is the same as joining them with `;`
        eff = joined(adef, "effect", ";\n", effects=True)
    else:
        eff = expression(adef, "effect", effects=True)
    cost = adef.get("cost", 1)
    if not isinstance(cost, int) or isinstance(cost, bool) or cost < 0:
        raise error_at(adef, "cost", "`cost` must be a non-negative integer")
    return ActionDef(name, params, lets, pres, eff, cost)
