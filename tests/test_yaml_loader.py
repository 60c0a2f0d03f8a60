"""The YAML loader's two paths: libyaml scans text that loads, PyYAML's own loader says
what is wrong with text that does not. Both must give the same nodes, places included,
since every `file:line:col` bcc prints comes from them."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings, strategies as st

from bcc.compiler import source
from bcc.compiler.source import load_yaml_text
from bcc.errors import BccError

ROOT = Path(source.__file__).resolve().parent.parent
FILES = sorted(p for folder in ("domains", "dungeons", "tests/structures", "tests/htn_yaml")
               for p in (ROOT / folder).glob("*.yaml"))

needs_libyaml = pytest.mark.skipif(source._FastLoader is None, reason="PyYAML built without libyaml")


def shape(node, out):
    """Every node's kind, tag, value and both places, depth first (aliases followed)."""
    if isinstance(node, source._Alias):
        out.append(("alias", node.start_mark.line, node.start_mark.column))
        return shape(node.node, out)
    out.append((type(node).__name__, node.tag, node.start_mark.line, node.start_mark.column,
                node.end_mark.line, node.end_mark.column))
    if isinstance(node, yaml.ScalarNode):
        out.append(node.value)
    elif isinstance(node, yaml.SequenceNode):
        for item in node.value:
            shape(item, out)
    else:
        for key, value in node.value:
            shape(key, out)
            shape(value, out)
    return out


def nodes(loader, text):
    return shape(loader(text, "x.yaml").get_single_node(), [])


@needs_libyaml
@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_both_loaders_give_the_same_nodes_on_shipped_files(path):
    text = path.read_text()
    assert nodes(source._FastLoader, text) == nodes(source._Loader, text)


@needs_libyaml
def test_marks_are_plain_so_the_cache_can_keep_them():
    root = source._FastLoader("a: [1, &x {b: c}, *x]\n", "x.yaml").get_single_node()
    seq = root.value[0][1]
    for node in (root, seq, seq.value[1], seq.value[2]):
        assert type(node.start_mark) is yaml.error.Mark


# Text with the places that differ between byte and character counts (non-ASCII before a
# value), quoting styles, block scalars and anchors.
_WORDS = st.sampled_from(["a", "é", "日本", "x y", "1", "-2", "yes", "~", "0o7", "1_0", "'q'", '"d"', "s: t"])


@needs_libyaml
@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(_WORDS, _WORDS, st.sampled_from(["plain", "flow", "block", "list"])), min_size=1,
                max_size=6))
def test_both_loaders_agree_on_generated_documents(entries):
    lines = []
    for i, (key, value, style) in enumerate(entries):
        k = f"k{i}{key if key.isalnum() else ''}"
        if style == "plain":
            lines.append(f"{k}: {value}")
        elif style == "flow":
            lines.append(f"{k}: [{value}, {{w: {value}}}]")
        elif style == "block":
            lines.append(f"{k}: |\n  {value}\n  {key}")
        else:
            lines.append(f"{k}:\n  - {value}\n  - {key}")
    text = "\n".join(lines) + "\n"
    results = []
    for loader in (source._FastLoader, source._Loader):
        try:
            results.append(nodes(loader, text))
        except yaml.YAMLError:
            results.append("error")
    if "error" not in results:
        assert results[0] == results[1], text


@pytest.mark.parametrize("text, line, col, words", [
    ("a: b: c\n", 1, 5, "mapping values are not allowed here"),          # PyYAML's wording, not libyaml's
    ("a: 1\n\tb: 2\n", 2, 1, "found character '\\t' that cannot start any token"),
    ("a: [1, 2\n", 2, 1, "expected ',' or ']'"),
])
def test_a_yaml_error_is_said_in_pyyaml_words_at_its_place(text, line, col, words):
    with pytest.raises(BccError) as caught:
        load_yaml_text(text, "f.yaml")
    err = caught.value
    assert words in err.message and (err.line, err.col) == (line, col), (err.message, err.line, err.col)


def test_control_characters_take_the_python_path_and_are_refused_at_their_place():
    with pytest.raises(BccError) as caught:
        load_yaml_text("a: b\nc: d\x07\n", "f.yaml")
    assert "#x0007" in caught.value.message and (caught.value.line, caught.value.col) == (2, 5)
