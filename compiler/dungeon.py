"""Load a dungeon file (spec section 5) and fill the domain's classes with objects.

The dungeon format is fixed by the spec; which class and attribute each part fills is
the domain's choice, read from its `dungeon:` section (so a domain with other class
names still loads spec-format dungeons).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path


from ..errors import BccError
from .definitions import Domain, Expr
from .domain import is_file, load_domain, resolve_domain_path
from .domain_exprs import condition
from .blocks import parse_blocks, place_blocks
from .limits import MAX_GRID_CELLS, MAX_REF_LENGTH, shorten
from .names import check_name, check_text, name_from_stem
from .structure import is_structure, read_blueprint, structure_expr
from .source import YList, YMap, check_keys, error_at, error_on, load_yaml, origin, suggest

DUNGEONS_DIR = Path(__file__).resolve().parent.parent / "dungeons"
FACINGS_KEYS = ("facing", "looking", "selected")
# Spec section 5; a domain may add lists of named objects (its `dungeon.lists`).
DUNGEON_KEYS = {"dungeon", "domain", "description", "height", "legend", "map", "agent", "inventory", "rooms",
                "goal", "extends", "width", "depth", "blocks", "task"}


@dataclass
class Dungeon:
    name: str
    path: str
    description: str
    domain: Domain
    width: int
    depth: int
    height: int
    grid_class: str
    grid: bytes                                    # dense value indices, [y][z][x] (index (y*depth + z)*width + x)
    objects: dict[str, tuple[str, dict]]           # named objects: name -> (class, attribute values)
    keyed: dict[str, dict[tuple, dict]] = field(default_factory=dict)  # class -> key -> attribute values
    goal: Expr | None = None
    agent_name: str = "agent"
    # (object name or (class, key), attribute) -> (YAML container, key): where a value was given
    where: dict = field(default_factory=dict)
    legend_columns: dict = field(default_factory=dict)  # map character -> column of value indices
    start_char: str | None = None
    structure: object = None                       # the goal's blueprint (structure.py), when it is one
    warnings: list = field(default_factory=list)   # BccErrors that do not stop loading (`file:line:col: warning: ...`)
    task: list | None = None                       # the task network to do, in order: [Expr of an ast.Call]

    @property
    def sizes(self) -> dict[str, int]:
        return {"width": self.width, "height": self.height, "depth": self.depth}


def shipped_dungeons() -> list[str]:
    return sorted(p.stem for p in DUNGEONS_DIR.glob("*.yaml"))


def resolve_dungeon_path(ref: str | Path) -> Path:
    """A dungeon is a path, or the name of a shipped one (a file stem in dungeons/)."""
    if len(str(ref)) > MAX_REF_LENGTH:
        raise BccError(f"a dungeon reference is a name or a path of at most {MAX_REF_LENGTH} characters, "
                       f"found {len(str(ref)):,}")
    path = Path(ref)
    if is_file(path):
        return path
    for cand in (DUNGEONS_DIR / f"{ref}.yaml", DUNGEONS_DIR / str(ref)):
        if is_file(cand):
            return cand
    raise BccError(f"no dungeon file or shipped dungeon named {shorten(repr(str(ref)))}"
                   f"{suggest(str(ref), shipped_dungeons())}; shipped: {', '.join(shipped_dungeons())}")


def _read_with_extends(path: Path, seen: tuple = ()) -> YMap:
    """A dungeon may `extends: other` and override top-level keys (e.g. only `goal`)."""
    data = load_yaml(path)
    if "extends" not in data:
        return data
    ref = data["extends"]
    if not isinstance(ref, str) or not ref:
        raise error_at(data, "extends", "`extends` names one dungeon (a shipped name or a path)")
    base_path = (path.parent / ref) if is_file(path.parent / ref) else None
    try:
        base_path = base_path or resolve_dungeon_path(str(ref))
    except BccError as exc:
        raise error_at(data, "extends", exc.message) from None
    if base_path.resolve() in seen or base_path.resolve() == path.resolve():
        raise error_at(data, "extends", f"dungeon files extend each other in a cycle ({base_path.name})")
    base = _read_with_extends(base_path, seen + (path.resolve(),))
    merged = YMap(base)
    merged.node, merged.src = base.node, base.src
    merged.nodes = dict(base.nodes)
    merged.srcs = {k: base.src_of(k) for k in base}
    for key in data:
        if key == "extends":
            continue
        merged[key] = data[key]
        merged.nodes[key] = data.nodes[key]
        merged.srcs[key] = data.src
    return merged


def load_dungeon(ref: str | Path, domain: Domain | None = None) -> Dungeon:
    path = resolve_dungeon_path(ref)
    data = _read_with_extends(path)
    # A world is a map (with its legend), or a size and `blocks` listed by position, or both.
    shape = {"legend", "map"} if "map" in data or "blocks" not in data else {"width", "depth"}
    check_keys(data, set(data) | DUNGEON_KEYS, {"domain", "height", "agent"} | shape, "a dungeon")
    if domain is None:
        dref = data["domain"]
        try:
            dpath = resolve_domain_path(str(dref), data.src_of("domain") and Path(data.src_of("domain").path))
        except BccError as exc:
            raise (error_at(data, "domain", exc.message) if "domain" in data else exc) from None
        from .cache import load_cached
        domain = load_cached(dpath, load_domain, kind="domains")   # parsed once per domain, not per dungeon
    return _Builder(domain, data, path).build()


class _Builder:
    def __init__(self, domain: Domain, data: YMap, path: Path):
        self.domain, self.data, self.path = domain, data, path
        b = domain.binding
        for key in ("grid", "agent"):
            if key not in b:
                raise error_on(b, f"the domain's `dungeon:` section needs `{key}` to load dungeon files")
        self.binding = b

    def cls(self, key: str, name) :
        if name not in self.domain.classes:
            raise error_at(self.binding, key, f"unknown class {name!r}{suggest(str(name), self.domain.classes)}")
        return self.domain.classes[name]

    def build(self) -> Dungeon:
        d, data = self.domain, self.data
        height = data["height"]
        if not isinstance(height, int) or isinstance(height, bool) or not 1 <= height <= 255:
            raise error_at(data, "height", "`height` must be a whole number of layers between 1 and 255")
        gclass = self.cls("grid", self.binding["grid"])
        value_attrs = [a for a in gclass.attrs if a not in gclass.key]
        if len(gclass.key) != 3 or len(value_attrs) != 1:
            raise error_at(self.binding, "grid", "the grid class needs a key of three attributes [x, y, z] and one other attribute")
        vtype = gclass.attrs[value_attrs[0]].type
        if vtype not in d.enums:
            raise error_at(self.binding, "grid", "the grid class's value attribute must have an enumerated type")
        self.venum = d.enums[vtype]
        self.default_index = self.venum.index(gclass.attrs[value_attrs[0]].default)
        if "map" in data:
            for key in ("width", "depth"):
                if key in data:
                    raise error_at(data, key, f"`{key}` is given by the map; give it only without `map`", on_key=True)
            legend = self.legend()
            rows, map_origin = self.rows(legend)
            depth, width = len(rows), len(rows[0])
        else:
            legend, rows, map_origin = {}, [], None
            width, depth = (self.size(key) for key in ("width", "depth"))
        if width * depth * height > MAX_GRID_CELLS:
            raise error_at(data, "map" if "map" in data else "width",
                           f"the dungeon has {width * depth * height:,} cells ({width} x {depth} "
                           f"x {height}); at most {MAX_GRID_CELLS:,}")
        grid = bytearray([self.default_index]) * (height * depth * width)
        for z, row in enumerate(rows):
            for x, ch in enumerate(row):
                column = legend[ch]
                if len(column) > height:
                    raise error_at(data["legend"], ch, f"the column {ch!r} has {len(column)} blocks but `height` is {height}")
                for y, value in enumerate(column):
                    grid[(y * depth + z) * width + x] = value
        if "blocks" in data:
            where = origin(data, "blocks")
            place_blocks(grid, parse_blocks(data["blocks"], where, self.venum.values), width, depth, height, where)
        if "dungeon" in data:
            name = check_name(data, "dungeon", data["dungeon"], "the dungeon name")
        else:
            name = name_from_stem(self.path.stem)
        if "description" in data:
            check_text(data, "description", data["description"], "the description")
        dungeon = Dungeon(name, str(self.path),
                          str(data.get("description", "")).strip(), d, width, depth, height,
                          gclass.name, bytes(grid), {})
        dungeon.legend_columns = legend
        if rows:
            self.unused_legend(dungeon, rows)
        self.agent(dungeon, rows, legend, map_origin)
        self.inventory(dungeon)
        self.rooms(dungeon)
        if "goal" in data and is_structure(data["goal"]):
            dungeon.structure = read_blueprint(data["goal"], tuple(self.venum.values), (width, height, depth))
            dungeon.goal = structure_expr(dungeon.structure, data["goal"], gclass.name, value_attrs[0])
        elif "goal" in data:
            dungeon.goal = condition(data, "goal")
        if "task" in data:
            from .domain_exprs import expression
            from .tasks import task_calls
            dungeon.task = task_calls(data, "task", expression)
        return dungeon

    def size(self, key: str) -> int:
        value = self.data[key]
        if not isinstance(value, int) or isinstance(value, bool) or not 1 <= value <= 4096:
            raise error_at(self.data, key, f"`{key}` must be a whole number of cells between 1 and 4096")
        return value

    def legend(self) -> dict[str, list[int]]:
        legend = self.data["legend"]
        if not isinstance(legend, YMap):
            raise error_at(self.data, "legend", "`legend` maps one character to a column of block names")
        out = {}
        for ch, column in legend.items():
            if not isinstance(ch, str) or len(ch) != 1 or not ch.isprintable():
                raise error_at(legend, ch, f"a legend key is one printable character, found {ch!r}", on_key=True)
            if not isinstance(column, YList):
                example = ", ".join(self.venum.values[-1:] * 2)   # a name of this domain's blocks
                raise error_at(legend, ch, f"a legend entry is a list of block names from y = 0 up, e.g. [{example}]")
            out[ch] = []
            for i, name in enumerate(column):
                if name not in self.venum.values:
                    raise error_at(column, i, f"unknown block type {name!r}{suggest(str(name), self.venum.values)}")
                out[ch].append(self.venum.index(name))
        return out

    def unused_legend(self, dungeon: Dungeon, rows) -> None:
        """A legend character the map never uses is allowed (a base dungeon's legend may
        serve its variants) but usually a typo in the map: say so, as a warning."""
        used = {ch for row in rows for ch in row}
        legend = self.data["legend"]
        for ch in legend:
            if ch not in used:
                where = error_at(legend, ch, f"warning: the legend character {ch!r} is never used in the map",
                                 on_key=True)
                dungeon.warnings.append(where)

    def rows(self, legend):
        text = self.data["map"]
        if not isinstance(text, str) or not text.strip():
            raise error_at(self.data, "map", "`map` is a block of text, one row per line (use `map: |`)")
        where = origin(self.data, "map")
        lines = text.splitlines()
        rows = [r.rstrip() for r in lines]
        while rows and not rows[-1]:
            rows.pop()
        width = len(rows[0])
        for z, row in enumerate(rows):
            if len(row) != width:
                raise where.error(f"row {z} has {len(row)} columns but row 0 has {width}; rows must be equally long",
                                  z + 1, min(len(row), width) + 1)
            for x, ch in enumerate(row):
                if ch not in legend:
                    raise where.error(f"unknown map character {ch!r}: add it to `legend`", z + 1, x + 1)
        return rows, where

    def agent(self, dungeon: Dungeon, rows, legend, map_origin):
        data, d = self.data, self.domain
        agent = data["agent"]
        if not isinstance(agent, YMap):
            raise error_at(data, "agent", "`agent` is a mapping with at least `start`")
        check_keys(agent, {"start", *FACINGS_KEYS}, {"start"}, "the agent")
        acls = self.cls("agent", self.binding["agent"])
        if len(acls.position) != 3:
            raise error_at(self.binding, "agent", f"class {acls.name!r} needs `position: [x, y, z]`")
        values = {a: adef.default for a, adef in acls.attrs.items()}
        start = agent["start"]
        if isinstance(start, str) and not rows:
            raise error_at(agent, "start", "without a `map`, the start is a position [x, y, z]")
        if isinstance(start, str):
            hits = [(x, z) for z, row in enumerate(rows) for x, ch in enumerate(row) if ch == start]
            if len(start) != 1 or not hits:
                raise error_at(agent, "start", f"the start {start!r} is not a character of the map")
            if len(hits) > 1:
                (x, z) = hits[1]
                raise map_origin.error(f"the start character {start!r} appears more than once in the map", z + 1, x + 1)
            x, z = hits[0]
            pos = (x, len(legend[start]), z)
            dungeon.start_char = start
        elif isinstance(start, YList) and len(start) == 3 and all(isinstance(v, int) and not isinstance(v, bool) for v in start):
            pos = tuple(start)
        else:
            raise error_at(agent, "start", "`start` is a map character or [x, y, z]")
        for axis, value, size in zip(acls.position, pos, (dungeon.width, dungeon.height, dungeon.depth)):
            if not 0 <= value < size:
                raise error_at(agent, "start", f"the start {list(pos)} is outside the dungeon ({dungeon.width} wide "
                                               f"x {dungeon.depth} deep x {dungeon.height} high)")
            values[axis] = value
            dungeon.where[(dungeon.agent_name, axis)] = (agent, "start")

        fields = self.binding.get("agent_fields") or {}
        for key in FACINGS_KEYS:
            if key not in agent:
                continue
            if key not in fields:
                raise error_at(agent, key, f"this domain does not say which attribute `{key}` sets", on_key=True)
            adef = acls.attrs[fields[key]]
            value = agent[key]
            if isinstance(value, str):
                if value not in adef.names:
                    raise error_at(agent, key, f"unknown {key} {value!r}; one of: {', '.join(adef.names)}")
                value = adef.names[value]
            if not isinstance(value, int) or isinstance(value, bool):
                raise error_at(agent, key, f"`{key}` must be a name or a number")
            values[adef.name] = value
            dungeon.where[(dungeon.agent_name, adef.name)] = (agent, key)

        dungeon.objects[dungeon.agent_name] = (acls.name, values)



    def inventory(self, dungeon: Dungeon):
        spec = self.binding.get("inventory")
        items = self.data.get("inventory")
        if spec is None:
            if items:
                raise error_at(self.data, "inventory", "this domain has no inventory")
            return
        icls = self.cls("inventory", spec["class"])
        if len(icls.key) != 1:
            raise error_at(spec, "class", "the inventory class needs a key of one attribute (the slot)")
        dungeon.keyed[icls.name] = {}
        if items is None:
            return
        items = _inventory_slots(items, self.data)
        item_attr, count_attr = icls.attrs[spec["item"]], icls.attrs[spec["count"]]
        ienum = self.domain.enums[item_attr.type]
        for slot, entry in enumerate(items):
            check_keys(entry, {"item", "count", "slot"}, {"item"}, "an inventory slot")
            slot = entry.get("slot", slot)
            if entry["item"] not in ienum.values:
                raise error_at(entry, "item", f"unknown item {entry['item']!r}{suggest(str(entry['item']), ienum.values)}")
            count = entry.get("count", 1)
            if not isinstance(count, int) or isinstance(count, bool) or count < 0:
                raise error_at(entry, "count", "`count` must be a whole number >= 0")
            if (slot,) in dungeon.keyed[icls.name]:
                raise error_at(entry, "slot" if "slot" in entry else "item", f"slot {slot} is filled twice")
            dungeon.keyed[icls.name][(slot,)] = {item_attr.name: entry["item"], count_attr.name: count}
            dungeon.where[((icls.name, (slot,)), count_attr.name)] = (entry, "count" if "count" in entry else "item")
            dungeon.where[((icls.name, (slot,)), "key")] = (entry, "slot" if "slot" in entry else "item")

    def rooms(self, dungeon: Dungeon):
        lists = dict(self.binding.get("lists") or {})
        if "rooms" in self.binding:
            lists["rooms"] = self.binding["rooms"]
        for key in self.data:
            if key not in lists and key not in DUNGEON_KEYS:
                raise error_at(self.data, key, f"unknown key {key!r} in a dungeon{suggest(str(key), set(DUNGEON_KEYS) | set(lists))}",
                               on_key=True)
        for key, spec in lists.items():
            self.object_list(dungeon, key, spec)

    def object_list(self, dungeon: Dungeon, key: str, spec):
        """A list of named objects (`rooms`, or one the domain declares in `dungeon.lists`), each
        {name, FIELD: value, ...}; a field fills one attribute, or several from a list."""
        entries = self.data.get(key)
        if not entries:
            return
        what = key[:-1] if key.endswith("s") else key
        article = "an" if what[:1] in "aeiou" else "a"
        fields = spec["fields"]
        required = set(spec.get("required", fields))
        shape = ", ".join(["name", *fields])
        if not isinstance(entries, YList):
            raise error_at(self.data, key, f"`{key}` is a list of {{{shape}}}")
        cls = self.domain.classes[spec["class"]]
        for i, entry in enumerate(entries):
            if not isinstance(entry, YMap):
                raise error_at(entries, i, f"{article} {what} is {{{shape}}}")
            check_keys(entry, {"name", *fields}, {"name", *required}, f"{article} {what}")
            name = check_name(entry, "name", entry["name"], f"{article} {what}'s name")
            if name in dungeon.objects:
                raise error_at(entry, "name", f"{what} name {name!r} must be a new name")
            values = {a: adef.default for a, adef in cls.attrs.items()}
            for fkey, attrs in fields.items():
                if fkey not in entry:
                    continue
                value = entry[fkey]
                if isinstance(attrs, list):
                    if not isinstance(value, list) or len(value) != len(attrs) or \
                            not all(isinstance(v, int) and not isinstance(v, bool) for v in value):
                        raise error_at(entry, fkey, f"`{fkey}` is a list of {len(attrs)} numbers")
                    values.update(zip(attrs, value))
                    for attr in attrs:
                        dungeon.where[(name, attr)] = (entry, fkey)
                    continue
                atype = cls.attrs[attrs].type
                enum = self.domain.enums.get(atype)
                if enum is not None and value not in enum.values:
                    raise error_at(entry, fkey, f"unknown {atype} {value!r}{suggest(str(value), enum.values)}")
                if atype == "bool" and not isinstance(value, bool) or \
                        atype == "int" and (not isinstance(value, int) or isinstance(value, bool)):
                    raise error_at(entry, fkey, f"`{fkey}` must be a {atype}")
                values[attrs] = value
                dungeon.where[(name, attrs)] = (entry, fkey)
            dungeon.objects[name] = (cls.name, values)


def _inventory_slots(items, data: YMap) -> YList:
    """The inventory as a list of {item, count[, slot]} mappings, slot 0 first. People also
    write a slot as its item alone (`- ITEM`, one of it) and the whole inventory as a
    mapping `{ITEM: COUNT, ...}` (slots in the order written); both become that list,
    keeping each value's place in the file for messages."""
    def entry(fields: dict, nodes: dict, src) -> YMap:
        made = YMap(fields)
        made.node, made.nodes, made.src, made.srcs = data.nodes["inventory"][1], nodes, src, {}
        return made

    if isinstance(items, YMap):
        slots = YList(entry({"item": name, "count": count}, {"item": items.nodes[name][:1] * 2,
                                                              "count": items.nodes[name]}, items.src_of(name))
                      for name, count in items.items())
        slots.node, slots.nodes, slots.src = items.node, [items.nodes[name][0] for name in items], items.src
        return slots
    if not isinstance(items, YList):
        raise error_at(data, "inventory", "`inventory` is a list of {item: NAME, count: N} (or NAME), slot 0 first")
    for slot, item in enumerate(items):
        if isinstance(item, str):
            items[slot] = entry({"item": item}, {"item": (items.nodes[slot], items.nodes[slot])}, items.src)
        elif not isinstance(item, YMap):
            raise error_at(items, slot, "an inventory slot is {item: NAME, count: N}, or NAME for one of it")
    return items
