"""The on-disk cache of loaded dungeons: hits give the same model, any change to a file
the load read makes it stale, and an entry never runs code."""
from __future__ import annotations

import os
import pickle
import shutil

import pytest

from bcc.compiler import cache, compile_dungeon
from bcc.compiler.domain import DOMAINS_DIR
from bcc.compiler.dungeon import DUNGEONS_DIR


@pytest.fixture
def cache_dir(tmp_path, monkeypatch):
    folder = tmp_path / "cache"
    monkeypatch.setenv("BCC_CACHE_DIR", str(folder))
    monkeypatch.delenv("BCC_NO_CACHE", raising=False)
    return folder


def entries(folder):
    return sorted((folder / "dungeons").glob("*.pickle")) if (folder / "dungeons").exists() else []


def copy_bridge(tmp_path):
    """bridge.yaml beside its own copy of the minecraft domain (so the test may edit it)."""
    shutil.copy(DOMAINS_DIR / "minecraft.yaml", tmp_path / "minecraft.yaml")
    text = (DUNGEONS_DIR / "bridge.yaml").read_text()
    assert "domain: minecraft" in text
    path = tmp_path / "bridge.yaml"
    path.write_text(text.replace("domain: minecraft", f"domain: {tmp_path / 'minecraft.yaml'}"))
    return path


def same_model(a, b):
    return (a.initial == b.initial and a.action_names == b.action_names and a.source == b.source
            and a.report == b.report)


def test_a_warm_load_gives_the_same_model(cache_dir):
    cold = compile_dungeon("bridge")
    assert len(entries(cache_dir)) == 1
    warm = compile_dungeon("bridge")
    assert same_model(cold, warm)
    # A hit does not load again: the entry's value comes back.
    calls = []
    assert cache.load_cached(DUNGEONS_DIR / "bridge.yaml", calls.append) is not None and calls == []


def test_an_edited_domain_makes_the_entry_stale(cache_dir, tmp_path):
    path = copy_bridge(tmp_path)
    first = compile_dungeon(path)
    domain = tmp_path / "minecraft.yaml"
    text = domain.read_text()
    # Rename an action: the cached dungeon must not be used any more.
    domain.write_text(text.replace("  move_forward:", "  walk_forward:", 1))
    second = compile_dungeon(path)
    assert "walk_forward" in second.action_names and "move_forward" in first.action_names


def test_a_second_dungeon_on_a_domain_reads_the_parsed_domain_from_the_cache(cache_dir, tmp_path, monkeypatch):
    """The domain has an entry of its own: a new dungeon on it (a generated house) does not
    parse it again; and that dungeon's entry still lists the domain's files, so editing the
    domain makes it stale although its load found the domain in the cache."""
    from bcc.compiler import dungeon
    first = copy_bridge(tmp_path)
    second = tmp_path / "bridge_again.yaml"
    second.write_text(first.read_text().replace("dungeon: bridge", "dungeon: bridge_again"))
    compile_dungeon(first)
    loads = []
    real = dungeon.load_domain
    monkeypatch.setattr(dungeon, "load_domain", lambda path: loads.append(path) or real(path))
    assert "move_forward" in compile_dungeon(second).action_names and loads == []
    domain = tmp_path / "minecraft.yaml"
    domain.write_text(domain.read_text().replace("  move_forward:", "  walk_forward:", 1))
    assert "walk_forward" in compile_dungeon(second).action_names and len(loads) == 1


def test_a_tampered_entry_never_runs_code(cache_dir, tmp_path):
    compile_dungeon("bridge")
    (entry,) = entries(cache_dir)
    marker = tmp_path / "ran"

    class Evil:
        def __reduce__(self):
            return (os.system, (f"touch {marker}",))

    entry.write_bytes(pickle.dumps({"version": cache._version(), "files": [], "value": Evil()}))
    model = compile_dungeon("bridge")     # the entry is refused, the dungeon loaded again
    assert not marker.exists()
    assert model.action_names[0] == "move_forward"
    with pytest.raises(pickle.UnpicklingError):
        cache.load_bytes(pickle.dumps(Evil()))


def test_the_cache_can_be_turned_off(cache_dir, monkeypatch):
    monkeypatch.setenv("BCC_NO_CACHE", "1")
    compile_dungeon("bridge")
    assert entries(cache_dir) == []


def test_xdg_cache_home_is_honoured(tmp_path, monkeypatch):
    monkeypatch.delenv("BCC_CACHE_DIR", raising=False)
    monkeypatch.delenv("BCC_NO_CACHE", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache.cache_dir() == tmp_path / "xdg" / "bcc"


def test_a_warm_solve_does_not_load_lark(cache_dir):
    """Everything parsed (the domain's expressions, its `dungeon.start` condition) is in the
    entry, so a warm `bcc solve` needs no parser: of two processes solving bridge, only
    the first imports lark."""
    import subprocess
    import sys
    probe = ("import sys; from bcc.cli import main\n"
             "try:\n    main(['solve', 'bridge'])\nexcept SystemExit:\n    pass\n"
             "print('lark' in sys.modules, file=sys.stderr)")
    runs = [subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120,
                           env=dict(os.environ, BCC_CACHE_DIR=str(cache_dir)))
            for _ in range(2)]
    assert [r.stderr.strip().splitlines()[-1] for r in runs] == ["True", "False"], runs[1].stderr


def test_the_pattern_database_is_built_once_per_model(cache_dir, monkeypatch):
    """A second compile of the same dungeon reads its pattern database from the cache; a
    different goal (other generated code) builds its own."""
    from bcc.heuristics import patterns
    calls = []
    build = patterns.build
    monkeypatch.setattr(patterns, "build", lambda *a, **k: calls.append(1) or build(*a, **k))
    first = compile_dungeon("tough_maze").data("pattern_database")
    again = compile_dungeon("tough_maze").data("pattern_database")
    assert len(calls) == 1 and again == first
    other = compile_dungeon("tough_maze", goal="agentOnBlock(agent, burlap_stone)").data("pattern_database")
    assert len(calls) == 2 and other != first
    monkeypatch.setenv("BCC_NO_CACHE", "1")
    assert compile_dungeon("tough_maze").data("pattern_database") == first and len(calls) == 3


def _analysis_files(folder):
    return sorted((folder / "bench").glob("*.pickle"))


def test_the_cache_stays_under_its_size_limit_least_recently_used_first(cache_dir, monkeypatch):
    """Entries of old bcc versions are never read again and big mazes write big entries:
    past BCC_CACHE_MAX_MB the least recently used entries go, and a read counts as a use."""
    monkeypatch.setenv("BCC_CACHE_MAX_MB", str(350_000 / 1024 / 1024))   # room for three 100 kB entries
    blob = lambda k: bytes([k]) * 100_000                                 # noqa: E731
    for k in range(3):
        cache.cached_analysis("bench", bytes([k]), lambda k=k: blob(k))
    which = {cache._read(p)[0]: p for p in _analysis_files(cache_dir)}   # first byte -> entry file
    assert sorted(which) == [0, 1, 2]
    for k, path in which.items():
        os.utime(path, (k + 1, k + 1))                  # written long ago, 0 first
    assert cache.cached_analysis("bench", bytes([0]), lambda: None) == blob(0)   # a read: 0 is recent again
    cache.cached_analysis("bench", bytes([3]), lambda: blob(3))                  # a fourth: over the limit
    left = sorted(cache._read(p)[0] for p in _analysis_files(cache_dir))
    assert left == [0, 3]                               # 1 and 2 were the least recently used
    assert sum(p.stat().st_size for p in _analysis_files(cache_dir)) <= cache.max_bytes()


def test_a_trim_touches_only_bccs_own_files(cache_dir, monkeypatch):
    monkeypatch.setenv("BCC_CACHE_MAX_MB", "0")
    (cache_dir / "notes").mkdir(parents=True)
    mine = cache_dir / "notes" / "results.pickle"
    mine.write_bytes(b"x" * 1000)
    stale_tmp = cache_dir / "notes" / f".{'a' * 40}.pickle.123.tmp"
    stale_tmp.write_bytes(b"")
    os.utime(stale_tmp, (1, 1))
    cache.cached_analysis("bench", b"k", lambda: b"y" * 1000)
    assert mine.exists() and not stale_tmp.exists()
    assert len(_analysis_files(cache_dir)) == 1    # the entry just written stays, even over the limit
