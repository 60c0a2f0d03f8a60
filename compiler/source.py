"""YAML loading that remembers where every value came from.

`load_yaml` returns plain dicts/lists (subclasses `YMap`/`YList`) whose values keep their
PyYAML nodes, so later stages can report `file:line:col` for any key, value, or a
character inside an expression or a map. PyYAML marks are 0-based; everything this
module hands out is 1-based.
"""
from __future__ import annotations

import difflib
import functools
from dataclasses import dataclass
from pathlib import Path

import yaml

from ..errors import BccError, read_input


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
    return load_yaml_text(read_input(path), str(path))


def load_yaml_text(text: str, path: str) -> YMap:
    src = SourceFile(path, text)
    loader = yaml.SafeLoader(text)
    try:
        root = loader.get_single_node()
        if root is None:
            raise BccError("the file is empty", path, 1, 1)
        data = _convert(root, loader, src)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        problem = exc.problem or exc.context or "invalid YAML"
        if "mapping values are not allowed" in problem:
            problem += " (a ': ' inside a value: quote the value, or write `exists x in C . ...`)"
        line, col = (mark.line + 1, mark.column + 1) if mark else (None, None)
        raise BccError(f"invalid YAML: {problem}", path, line, col) from None
    except yaml.YAMLError as exc:
        raise BccError(f"invalid YAML: {exc}", path) from None
    finally:
        loader.dispose()
    if not isinstance(data, YMap):
        raise BccError("expected a mapping of keys at the top level", path, 1, 1)
    return data


def _convert(node: yaml.Node, loader: yaml.SafeLoader, src: SourceFile):
    if isinstance(node, yaml.MappingNode):
        out = YMap()
        out.node, out.nodes, out.src = node, {}, src
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode) or key_node.tag == "tag:yaml.org,2002:merge":
                m = key_node.start_mark
                raise BccError("only plain keys are supported here", src.path, m.line + 1, m.column + 1)
            key = loader.construct_object(key_node, deep=True)
            if key in out:
                m = key_node.start_mark
                raise BccError(f"duplicate key {key!r}", src.path, m.line + 1, m.column + 1)
            out[key] = _convert(value_node, loader, src)
            out.nodes[key] = (key_node, value_node)
        return out
    if isinstance(node, yaml.SequenceNode):
        out = YList(_convert(item, loader, src) for item in node.value)
        out.node, out.nodes, out.src = node, list(node.value), src
        return out
    return loader.construct_object(node, deep=True)


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
    import bisect
    k = bisect.bisect_right(starts, index) - 1
    return k + 1, index - starts[k] + 1


def check_keys(container: YMap, allowed: set[str], required: set[str], what: str) -> None:
    """Unknown keys (with a did-you-mean) and missing keys are errors with positions."""
    for key in container:
        if key not in allowed:
            close = difflib.get_close_matches(str(key), sorted(allowed), n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise error_at(container, key, f"unknown key {key!r} in {what}{hint}", on_key=True)
    for key in sorted(required):
        if key not in container:
            raise error_on(container, f"{what} is missing the key {key!r}")


def suggest(name: str, options) -> str:
    close = difflib.get_close_matches(name, sorted(options), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""
