"""YAML loading that remembers where every value came from.

`load_yaml` returns plain dicts/lists (subclasses `YMap`/`YList`) whose values keep their
PyYAML nodes, so later stages can report `file:line:col` for any key, value, or a
character inside an expression or a map. PyYAML marks are 0-based; everything this
module hands out is 1-based.
"""
from __future__ import annotations

import bisect
import difflib
import functools
import re
from dataclasses import dataclass
from pathlib import Path

import yaml

from ..errors import BccError, read_input
from .cache import note_read
from .limits import MAX_ALIAS_VALUES, MAX_FILE_BYTES, MAX_YAML_DEPTH, int_error, number_error, shorten


class YMap(dict):
    """A YAML mapping; `.node` is the mapping node, `.nodes[key]` the (key, value) nodes.

    `.srcs[key]` names the file of a key that came from another file (dungeon `extends`)."""
    node: yaml.Node
    nodes: dict
    src: "SourceFile"
    srcs: dict

    def src_of(self, key) -> "SourceFile":
        return getattr(self, "srcs", {}).get(key, self.src)


class YList(list):
    """A YAML sequence; `.node` is the sequence node, `.nodes[i]` the item nodes."""
    node: yaml.Node
    nodes: list
    src: "SourceFile"


@dataclass(frozen=True)
class SourceFile:
    path: str
    text: str

    @functools.cached_property
    def line_starts(self) -> list:
        """Offsets where each line begins (computed once per file, used for every scalar)."""
        starts, pos = [0], 0
        for line in self.text.splitlines(keepends=True):
            pos += len(line)
            starts.append(pos)
        return starts


@dataclass(frozen=True)
class Origin:
    """Where an embedded text (an expression, a map) lives in its file.

    Either the text starts at `line`/`col` and further lines start at column `indent`
    (block scalars), or `positions` gives the file (line, col) of every character of the
    text -- needed where YAML folds lines, strips quotes or expands escapes."""
    path: str | None
    line: int
    col: int
    indent: int = 1
    positions: tuple | None = None
    text: str | None = None

    def locate(self, line: int, col: int) -> tuple[int, int]:
        """File position of (line, col) inside the embedded text (both 1-based)."""
        if self.positions is not None:
            lines = self.text.split("\n")
            offset = sum(len(l) + 1 for l in lines[:max(line - 1, 0)]) + col - 1
            if not self.positions:
                return self.line, self.col
            if offset < len(self.positions):
                return self.positions[max(offset, 0)]
            last_line, last_col = self.positions[-1]
            return last_line, last_col + 1 + offset - len(self.positions)
        if line <= 1:
            return self.line, self.col + col - 1
        return self.line + line - 1, self.indent + col - 1

    def error(self, message: str, line: int = 1, col: int = 1) -> BccError:
        fl, fc = self.locate(line, col)
        return BccError(message, self.path, fl, fc)


def load_yaml(path: str | Path) -> YMap:
    """Parse one YAML document into YMap/YList with positions; bad YAML is a BccError."""
    return load_yaml_text(_read_source(path), str(path))


def _read_source(path: str | Path) -> str:
    """The file's text, refused past `MAX_FILE_BYTES` (read no further) or where it is not UTF-8."""
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_FILE_BYTES + 1)
    except (OSError, ValueError):
        note_read(path, None)    # not a plain file: a load that reads it is not cached
        return read_input(path)  # the same one-line message as every other file bcc reads
    if len(data) > MAX_FILE_BYTES:
        raise BccError(f"the file is larger than {MAX_FILE_BYTES // 2**20} MiB", str(path))
    note_read(path, data)   # the compiled-dungeon cache keys on every file a load reads
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        col = len(data[data.rfind(b"\n", 0, exc.start) + 1:exc.start].decode("utf-8", "replace")) + 1
        raise BccError(f"the file is not UTF-8 text (byte 0x{data[exc.start]:02x})", str(path), line, col) from None


_TIMESTAMP = "tag:yaml.org,2002:timestamp"
# The tags of plain data. Others (!!timestamp, !!binary, !!set, !!omap, !!pairs, !custom)
# make objects the loaders never expect, so they are refused where they are written.
_PLAIN_TAGS = {f"tag:yaml.org,2002:{t}" for t in ("str", "int", "bool", "null", "float", "seq", "map")}
_SURROGATE = re.compile("[\ud800-\udfff]")


@dataclass(slots=True)
class _Alias:
    """Where a `*name` alias is used (PyYAML's composer returns the anchored node itself,
    losing the place): lets loops and alias bombs be reported at the alias. A data class,
    so the on-disk cache may rebuild a domain that uses aliases (cache.py builds only data
    classes)."""
    node: yaml.Node
    start_mark: object


class _Checks:
    """What bcc's loaders add to PyYAML's: bounded nesting, bounded numbers, no timestamps,
    and where each `*name` alias is used. An unquoted `2001-01-01` stays text (a dungeon
    has no use for dates)."""
    yaml_implicit_resolvers = {first: [(tag, rx) for tag, rx in resolvers if tag != _TIMESTAMP]
                               for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()}

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            mark = self.peek_event().start_mark
            return _Alias(super().compose_node(parent, index), mark)
        self.bcc_depth += 1
        try:
            if self.bcc_depth > MAX_YAML_DEPTH:
                m = self.peek_event().start_mark
                raise BccError(f"lists and mappings are nested more than {MAX_YAML_DEPTH} levels deep",
                               self.bcc_path, m.line + 1, m.column + 1)
            return super().compose_node(parent, index)
        finally:
            self.bcc_depth -= 1

    def construct_yaml_int(self, node):
        problem = number_error(node.value)
        if problem is None:
            value = super().construct_yaml_int(node)
            problem = int_error(value)
            if problem is None:
                return value
        raise BccError(problem, self.bcc_path, *node_pos(node))


class _Loader(_Checks, yaml.SafeLoader):
    """PyYAML's own loader, all Python: its messages and places are the ones bcc reports."""

    def __init__(self, text: str, path: str):
        yaml.SafeLoader.__init__(self, text)
        self.bcc_path, self.bcc_depth = path, 0


_Loader.add_constructor("tag:yaml.org,2002:int", _Loader.construct_yaml_int)

try:
    from yaml.cyaml import CParser
except ImportError:     # PyYAML built without libyaml
    CParser = None

if CParser is not None:
    class _FastLoader(_Checks, yaml.composer.Composer, CParser, yaml.constructor.SafeConstructor,
                      yaml.resolver.Resolver):
        """libyaml scans and parses (about six times faster on a large domain); the nodes
        are composed by PyYAML's Python composer, so the checks above and the places of
        nodes are the same. Used only for text that loads: any YAML error is reported by
        `_Loader` instead, with PyYAML's wording."""

        def __init__(self, text: str, path: str):
            CParser.__init__(self, text)
            yaml.composer.Composer.__init__(self)
            yaml.constructor.SafeConstructor.__init__(self)
            yaml.resolver.Resolver.__init__(self)
            self.bcc_path, self.bcc_depth = path, 0

        def get_single_node(self):
            root = super().get_single_node()
            _plain_marks(root)
            return root

    _FastLoader.add_constructor("tag:yaml.org,2002:int", _FastLoader.construct_yaml_int)
else:
    _FastLoader = None


def _plain_marks(root) -> None:
    """libyaml's marks as PyYAML's own Mark (name, index, line, column): the compiled-dungeon
    cache pickles the nodes, and its unpickler builds only plain data classes."""
    made: dict = {}     # id of a C mark -> (that mark, kept so its id is not reused; its plain copy)

    def plain(mark):
        key = id(mark)
        if key not in made:
            made[key] = (mark, yaml.error.Mark(mark.name, mark.index, mark.line, mark.column, None, None))
        return made[key][1]

    seen: set[int] = set()
    todo = [root]
    while todo:
        node = todo.pop()
        if node is None or id(node) in seen:
            continue
        seen.add(id(node))
        if isinstance(node, _Alias):
            node.start_mark = plain(node.start_mark)
            todo.append(node.node)
            continue
        node.start_mark, node.end_mark = plain(node.start_mark), plain(node.end_mark)
        if isinstance(node, yaml.SequenceNode):
            todo.extend(node.value)
        elif isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                todo.append(key)
                todo.append(value)


def load_yaml_text(text: str, path: str) -> YMap:
    if len(text) > MAX_FILE_BYTES:
        raise BccError(f"the text is larger than {MAX_FILE_BYTES // 2**20} MiB", path)
    src = SourceFile(path, text)
    if _FastLoader is not None and not yaml.reader.Reader.NON_PRINTABLE.search(text):
        loader = _FastLoader(text, path)
        try:
            return _converted(loader, src)
        except yaml.YAMLError:
            pass        # said again below, in PyYAML's words
        finally:
            loader.dispose()
    try:
        loader = _Loader(text, path)
    except yaml.reader.ReaderError as exc:
        raise _reader_error(exc, src) from None
    try:
        return _converted(loader, src)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        problem = exc.problem or exc.context or "invalid YAML"
        if "mapping values are not allowed" in problem:
            problem += " (a ': ' inside a value: quote the value, or write `exists x in C . ...`)"
        line, col = (mark.line + 1, mark.column + 1) if mark else (None, None)
        raise BccError(f"invalid YAML: {problem}", path, line, col) from None
    except yaml.reader.ReaderError as exc:
        raise _reader_error(exc, src) from None
    except yaml.YAMLError as exc:
        raise BccError(f"invalid YAML: {shorten(str(exc).splitlines()[0], 200)}", path) from None
    finally:
        loader.dispose()


def _converted(loader, src: SourceFile) -> YMap:
    root = loader.get_single_node()
    if root is None:
        raise BccError("the file is empty", src.path, 1, 1)
    data = _Converter(loader, src).convert(root, 0)
    if not isinstance(data, YMap):
        raise BccError("expected a mapping of keys at the top level", src.path, 1, 1)
    return data


def _reader_error(exc, src: SourceFile) -> BccError:
    """PyYAML refuses control characters (NUL, ESC, ...) with an offset into the text."""
    where = _line_col(src.line_starts, exc.position) if isinstance(exc.position, int) else (None, None)
    char = exc.character
    shown = f"#x{char:04x}" if isinstance(char, int) else repr(char)
    return BccError(f"invalid YAML: the character {shown} is not allowed in YAML text "
                    "(control characters other than tab and line breaks)", src.path, *where)


class _Converter:
    """YAML nodes -> YMap/YList/values, with the limits that a node graph needs: a value that
    contains itself through an alias, aliases that repeat more than `MAX_ALIAS_VALUES`
    values, nesting deeper than `MAX_YAML_DEPTH` once aliases are expanded, text with
    lone surrogates, and tags other than plain data."""

    def __init__(self, loader: _Loader, src: SourceFile):
        self.loader, self.src = loader, src
        self.seen: set[int] = set()
        self.active: set[int] = set()
        self.repeated = 0
        self.via: _Alias | None = None  # the outermost alias being expanded, for error positions

    def error(self, node, message: str) -> BccError:
        return BccError(message, self.src.path, *node_pos(node))

    def convert(self, node, depth: int):
        if isinstance(node, _Alias):
            if id(node.node) in self.active:
                raise self.error(node, "this alias refers to a value that contains it (a YAML loop)")
            outer = self.via is None
            if outer:
                self.via = node
            try:
                return self.convert(node.node, depth)
            finally:
                if outer:
                    self.via = None
        if depth > MAX_YAML_DEPTH:  # only through an alias: the composer bounds the rest
            raise self.error(self.via or node, f"lists and mappings are nested more than {MAX_YAML_DEPTH} "
                                               "levels deep once aliases are expanded")
        if id(node) in self.seen:
            self.repeated += 1
            if self.repeated > MAX_ALIAS_VALUES:
                raise self.error(node, f"YAML aliases repeat more than {MAX_ALIAS_VALUES:,} values; "
                                       "write the values out or use fewer aliases")
        self.seen.add(id(node))
        if node.tag not in _PLAIN_TAGS:
            raise self.error(node, f"the YAML tag {_tag_name(node.tag)} is not supported: bcc reads text, "
                                   "whole numbers, true/false, null, lists and mappings")
        if isinstance(node, yaml.MappingNode):
            return self.mapping(node, depth)
        if isinstance(node, yaml.SequenceNode):
            self.active.add(id(node))
            out = YList(self.convert(item, depth + 1) for item in node.value)
            self.active.discard(id(node))
            out.node, out.nodes, out.src = node, [_target(item) for item in node.value], self.src
            return out
        return self.scalar(node)

    def mapping(self, node, depth: int) -> YMap:
        out = YMap()
        out.node, out.nodes, out.src = node, {}, self.src
        self.active.add(id(node))
        for key_node, value_node in node.value:
            key_node = _target(key_node)
            if not isinstance(key_node, yaml.ScalarNode) or key_node.tag == "tag:yaml.org,2002:merge":
                raise self.error(key_node, "only plain keys are supported here")
            key = self.scalar(key_node)
            if key in out:
                raise self.error(key_node, f"duplicate key {shorten(repr(key))}")
            out[key] = self.convert(value_node, depth + 1)
            out.nodes[key] = (key_node, _target(value_node))
        self.active.discard(id(node))
        return out

    def scalar(self, node):
        if node.tag not in _PLAIN_TAGS:
            raise self.error(node, f"the YAML tag {_tag_name(node.tag)} is not supported: bcc reads text, "
                                   "whole numbers, true/false, null, lists and mappings")
        try:
            value = self.loader.construct_object(node, deep=True)
        except (ValueError, TypeError):  # an explicit tag on text that is not of its type: `!!int x`
            raise self.error(node, f"{shorten(repr(node.value))} is not a valid {_tag_name(node.tag)}") from None
        if isinstance(value, str) and _SURROGATE.search(value):
            raise self.error(node, "the text holds a lone surrogate (such as \\ud800), which is not a character")
        return value


def _target(node):
    return node.node if isinstance(node, _Alias) else node


def _tag_name(tag: str | None) -> str:
    if tag and tag.startswith("tag:yaml.org,2002:"):
        return "!!" + tag[len("tag:yaml.org,2002:"):]
    return shorten(str(tag), 40)


# ---- positions -------------------------------------------------------------------
def node_pos(node: yaml.Node) -> tuple[int, int]:
    return node.start_mark.line + 1, node.start_mark.column + 1


def value_node(container, key) -> yaml.Node:
    if isinstance(container, YMap):
        return container.nodes[key][1]
    return container.nodes[key]


def error_at(container, key, message: str, on_key: bool = False) -> BccError:
    """A BccError pointing at container[key] (its value, or its key with on_key)."""
    if isinstance(container, YMap) and key in container.nodes:
        node = container.nodes[key][0 if on_key else 1]
        return BccError(message, container.src_of(key).path, *node_pos(node))
    elif isinstance(container, YList) and isinstance(key, int) and key < len(container.nodes):
        node = container.nodes[key]
    else:
        return error_on(container, message)
    return BccError(message, container.src.path, *node_pos(node))


def error_on(container, message: str) -> BccError:
    """A BccError pointing at a whole mapping or list."""
    node = getattr(container, "node", None)
    src = getattr(container, "src", None)
    if node is None or src is None:
        return BccError(message)
    return BccError(message, src.path, *node_pos(node))


def origin(container, key) -> Origin:
    """Where the text of the scalar container[key] lives (for expressions and maps)."""
    node = value_node(container, key)
    src = container.src_of(key) if isinstance(container, YMap) else container.src
    line, col = node_pos(node)
    style = getattr(node, "style", None)
    value = node.value if isinstance(node, yaml.ScalarNode) else None
    lines = src.text.splitlines()
    if style == "|" and isinstance(value, str):
        # A literal block keeps its lines one for one, from the line after the indicator.
        indicator = lines[line - 1] if line - 1 < len(lines) else ""
        digits = [c for c in indicator[col:] if c.isdigit()]
        if digits:
            indent = len(indicator) - len(indicator.lstrip(" ")) + int(digits[0]) + 1
        else:
            first = next((l for l in lines[line:] if l.strip()), "")
            indent = len(first) - len(first.lstrip(" ")) + 1
        return Origin(src.path, line + 1, indent, indent)
    if not isinstance(value, str):
        return Origin(src.path, line, col, 1)
    return Origin(src.path, line, col, 1, _align(src, node, value), value)


def _align(src: SourceFile, node, value: str) -> tuple:
    """The file (line, col) of each character of a scalar's value: walk the value and the
    source text together, skipping what YAML removed (quotes, folded line breaks and
    indentation, escape sequences); a character not found nearby maps to where we are."""
    text = src.text
    start, end = node.start_mark.index, node.end_mark.index
    starts = src.line_starts
    out, i = [], start
    for ch in value:
        j = i
        limit = min(end, i + 12)
        while j < limit and text[j] != ch and not (ch == " " and text[j] == "\n"):
            j += 1
        if j < limit:
            i = j
        out.append(_line_col(starts, min(i, max(end - 1, start))))
        i += 1
    return tuple(out)


def _line_col(starts: list, index: int) -> tuple[int, int]:
    k = bisect.bisect_right(starts, index) - 1
    return k + 1, index - starts[k] + 1


def check_keys(container: YMap, allowed: set[str], required: set[str], what: str) -> None:
    """Unknown keys (with a did-you-mean) and missing keys are errors with positions."""
    for key in container:
        if key not in allowed:
            raise error_at(container, key, f"unknown key {shorten(repr(key))} in {what}{suggest(key, allowed)}",
                           on_key=True)
    for key in sorted(required):
        if key not in container:
            raise error_on(container, f"{what} is missing the key {key!r}")


# Words people bring from PDDL, Python or plain English for a key or type bcc spells
# otherwise; offered when the option is there and the spelling is not close to anything.
_SYNONYMS = {
    "precondition": "pre", "preconditions": "pre", "requires": "pre", "require": "pre", "conditions": "pre",
    "condition": "pre", "when": "pre", "effects": "effect", "do": "effect", "parameters": "params",
    "param": "params", "args": "params", "arguments": "params", "integer": "int", "number": "int",
    "boolean": "bool", "attrs": "attributes", "fields": "attributes", "goals": "goal", "objective": "goal",
    "name": "dungeon", "title": "dungeon", "size": "height", "start": "agent", "items": "inventory",
}


def suggest(name: str, options) -> str:
    """A did-you-mean hint; options may hold any YAML keys (numbers, true, null)."""
    choices = sorted({str(o) for o in options})
    close = difflib.get_close_matches(str(name), choices, n=1)
    if not close and _SYNONYMS.get(str(name).lower()) in choices:
        close = [_SYNONYMS[str(name).lower()]]
    return f" (did you mean {close[0]!r}?)" if close else ""
