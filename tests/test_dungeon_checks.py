"""Mistakes that used to pass silently: an agent started inside a block, a legend
character the map never uses, and the scene's keys (the same as `bcc play`'s)."""
from __future__ import annotations

import re

from click.testing import CliRunner

from bcc.cli import main
from bcc.compiler import compile_dungeon
from bcc.keys import KEYS, key_map

DUNGEON = """\
dungeon: small
domain: minecraft
height: 3
legend:
  "#": [bedrock, bedrock, bedrock]
  ".": [bedrock]
  "G": [gold]
{extra}map: |
  #####
  #..G#
  #####
agent:
  start: {start}
goal: agentOnBlock(agent, gold)
"""


def write(tmp_path, start="[1, 1, 1]", extra=""):
    path = tmp_path / "small.yaml"
    path.write_text(DUNGEON.format(start=start, extra=extra))
    return str(path)


def test_an_agent_started_inside_a_wall_is_refused_at_its_start(tmp_path):
    # (0, 1, 0) is the corner wall's second block: before, this compiled and ended in
    # "no plan exists" with no hint.
    path = write(tmp_path, start="[0, 1, 0]")
    result = CliRunner().invoke(main, ["solve", path])
    assert result.exit_code == 2
    assert re.fullmatch(rf"{re.escape(path)}:13:10: the dungeon's start breaks its domain's start condition "
                        r"`passable\(agent.x, agent.y, agent.z\) and .*` \(is the agent inside a block\?\)\n",
                        result.stderr)


def test_a_legend_character_the_map_never_uses_is_a_warning_with_its_position(tmp_path):
    path = write(tmp_path, extra="")
    text = open(path).read().replace('  "G": [gold]\n', '  "G": [gold]\n  "M": [bedrock]\n')
    open(path, "w").write(text)
    result = CliRunner().invoke(main, ["solve", path])
    assert result.exit_code == 0  # still solved: a base dungeon's legend may serve its variants
    line = f"{path}:8:3: warning: the legend character 'M' is never used in the map"
    assert line in result.stderr.splitlines()
    assert compile_dungeon(path).report["warnings"] == [line]


def test_no_shipped_dungeon_has_a_warning():
    from bcc.compiler import shipped_dungeons
    for name in shipped_dungeons():
        assert compile_dungeon(name).report["warnings"] == [], name


def test_the_web_page_and_the_terminal_share_one_key_table():
    from bcc.serve.scene import scene
    model = compile_dungeon("bridge")
    keys = scene(model, [])["keys"]
    assert keys == {key: model.action_names[i] for key, i in key_map(model.action_names).items()}
    assert {keys[k] for k in KEYS.values()} == set(KEYS)  # every usual action by its letter
