"""A domain's `types:` section: enumerations, their values (with ids) and properties
(plain, typed, and tables indexed by another enumeration), extended by a later domain.

Apart from the loader (domain.py) because types are read in an order of their own --
every name declared first, property values checked once every type is complete -- and
are most of what can go wrong in a domain file.
"""
from __future__ import annotations

from ..errors import BccError
from .definitions import BUILTIN_TYPES, EnumType
from .limits import shorten
from .names import check_name
from .source import YList, YMap, check_keys, error_at, error_on, suggest


def load_enums(section, inherited: dict) -> dict[str, EnumType]:
    """Enumerations; a type the base domain has already gets the new values appended."""
    enums = {name: EnumType(e.name, list(e.values), list(e.ids), {p: list(v) for p, v in e.properties.items()},
                            dict(e.prop_types), dict(e.prop_defaults), dict(e.prop_per))
             for name, e in inherited.items()}
    if section is None:
        return enums
    if not isinstance(section, YMap):
        raise error_on(section, "`types` must map type names to their values")
    _declare(section, enums)
    pending = []   # (enum, property, value, container, key, is a table entry): checked once all are read
    for tname, tdef in section.items():
        if not isinstance(tdef, YMap):
            raise error_at(section, tname, "a type needs `values` (a list or a mapping)")
        check_keys(tdef, {"values", "properties"}, {"values"}, f"type {tname!r}")
        defaults = _load_properties(tname, tdef, enums, pending)
        _load_values(tname, tdef, enums[tname], inherited, defaults, pending)
    for enum, p, v, where, key, entry in pending:
        per = enum.prop_per.get(p)
        if entry and key not in enums[per].values:
            raise error_at(where, key, f"{shorten(repr(key))} is not a value of {per!r}, which indexes the table "
                                       f"{enum.name}.{p}{suggest(str(key), enums[per].values)}", on_key=True)
        _check_property_value(enums, enum, p, v, where, key)
    _store_dense(enums)
    return enums


def _declare(section, enums: dict) -> None:
    """Every new type's name, before any is read: properties may be of another new type."""
    for tname in section:
        check_name(section, tname, tname, "a type name")
        if tname in BUILTIN_TYPES:
            raise error_at(section, tname, f"{tname!r} is a built-in type", on_key=True)
        if tname not in enums:
            enums[tname] = EnumType(tname, [], [], {}, {}, {})


def _load_properties(tname: str, tdef, enums: dict, pending: list) -> dict:
    """The properties type `tname` declares (each existing value gets the default): their
    defaults by name."""
    enum = enums[tname]
    props = tdef.get("properties") or YMap()
    if not isinstance(props, YMap):
        raise error_at(tdef, "properties", "`properties` maps property names to defaults")
    defaults = {}
    for p, d in props.items():
        check_name(props, p, p, "a property name")
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
    return defaults


def _load_values(tname: str, tdef, enum: EnumType, inherited: dict, defaults: dict, pending: list) -> None:
    """The values type `tname` lists: new ones appended with their id and properties; a
    base domain's value listed again sets its properties only."""
    inherited_values = set(inherited[tname].values) if tname in inherited else set()
    values = tdef["values"]
    if isinstance(values, YList):
        items = [(v, YMap()) for v in values]
        for i, v in enumerate(values):
            check_name(values, i, v, "a value")
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


def _store_dense(enums: dict) -> None:
    """Enumeration-valued properties (and table entries, and defaults) stored as dense
    indices, once every type is complete."""
    for enum in enums.values():
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
