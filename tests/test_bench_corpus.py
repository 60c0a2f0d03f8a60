"""bench/corpus.py on a small pairs file of its own: the pooled figures are run on each
shuffle and the reported figure is their mean; each shuffle's figures are those of
`bcc corpus evaluate`'s folds with that seed."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from bench_harness import load_bench

ROOT = Path(__file__).resolve().parent.parent

ROOMS = {"red": ["go to the red room", "walk into the red room", "head to the pink room", "enter the red room"],
         "green": ["go to the green room", "walk into the green room", "head to the green room", "enter green"]}
CHAIR = {"blue": ["take the chair to the blue room", "push the chair into the blue room",
                  "bring the chair to the purple room", "move the chair to blue"],
         "green": ["take the chair to the green room", "push the chair into the green room",
                   "bring the chair to green", "move the chair to the green room"]}


def pairs_file(path: Path) -> Path:
    lines = []
    for room, commands in ROOMS.items():
        lines += [(c, f"agentInRoom(agent, {room})") for c in commands]
    for room, commands in CHAIR.items():
        lines += [(c, f"blockInRoom(chair, {room})") for c in commands]
    path.write_text("".join(json.dumps({"id": k, "level": f"L{k % 2}", "command": c, "task": t}) + "\n"
                            for k, (c, t) in enumerate(lines)))
    return path


def test_mean_of_shuffles_averages_each_level_and_keeps_the_shuffles():
    bench = load_bench("corpus")
    by_seed = {"0": {"pooled": {"L0": 80.0, "L1": 90.0}, "overall": 85.0, "train_seconds": 1.0},
               "1": {"pooled": {"L0": 70.0, "L1": 85.0}, "overall": 77.5, "train_seconds": 3.0}}
    entry = bench.mean_of_shuffles(by_seed)
    assert entry["pooled"] == {"L0": 75.0, "L1": 87.5}
    assert entry["overall"] == 81.25 and entry["train_seconds"] == 2.0
    assert entry["by_seed"] == by_seed


@pytest.mark.parametrize("text", ["", "0,0", "a", "1;2"])
def test_seeds_must_be_distinct_numbers(text):
    bench = load_bench("corpus")
    with pytest.raises(SystemExit) as exc:
        bench.main(["--seeds", text])
    assert exc.value.code == 2


@pytest.mark.slow
def test_the_corpus_benchmark_reports_each_shuffle_and_their_mean(tmp_path):
    from bcc.grounding import pairs
    data = pairs_file(tmp_path / "pairs.jsonl")
    out = tmp_path / "corpus.json"
    done = subprocess.run([sys.executable, str(ROOT / "bench" / "corpus.py"), "--pairs", str(data), "--folds", "2",
                           "--seeds", "3,5", "--pooled-only", "-o", str(out)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "mean of 2 shuffles (seeds 3, 5)" in done.stdout
    report = json.loads(out.read_text())
    assert report["seeds"] == [3, 5] and report["folds"] == 2 and report["count"] == 16
    rows = pairs.load(data, "cleanup")
    for mode in pairs.MODES:
        entry = report["results"][mode]
        assert set(entry["by_seed"]) == {"3", "5"} and "per_level" not in entry
        for seed in (3, 5):   # each shuffle is `bcc corpus evaluate --folds 2 --seed N` (same code, run again here)
            again = pairs.evaluate(pairs.folds(rows, 2, seed), mode)
            mine = entry["by_seed"][str(seed)]
            assert mine["overall"] == pytest.approx(100 * again["accuracy"])
            assert mine["pooled"] == pytest.approx({lv: 100 * v["accuracy"] for lv, v in again["by_level"].items()})
        for lv in ("L0", "L1"):
            assert entry["pooled"][lv] == pytest.approx(sum(e["pooled"][lv] for e in entry["by_seed"].values()) / 2)


@pytest.mark.slow
def test_a_resumed_nested_run_keeps_finished_shuffles_and_summarises_all(tmp_path):
    """--resume runs only the shuffles the file lacks; the summary over all of them is the
    one a single run of every shuffle gives (its figures are per-shuffle means)."""
    data = pairs_file(tmp_path / "pairs.jsonl")
    out = tmp_path / "nested.json"
    base = [sys.executable, str(ROOT / "bench" / "corpus.py"), "--pairs", str(data), "--folds", "2", "--nested",
            "--workers", "1", "-o", str(out)]
    first = subprocess.run(base + ["--seeds", "3"], capture_output=True, text=True)
    assert first.returncode == 0, first.stderr
    seed3 = json.loads(out.read_text())["nested"]["by_seed"]["3"]
    second = subprocess.run(base + ["--seeds", "3,5", "--resume"], capture_output=True, text=True)
    assert second.returncode == 0, second.stderr
    assert "seed 3: kept from the previous run" in second.stderr
    report = json.loads(out.read_text())
    assert report["nested"]["by_seed"]["3"] == seed3 and set(report["nested"]["by_seed"]) == {"3", "5"}
    together = subprocess.run(base[:-1] + [str(tmp_path / "all.json"), "--seeds", "3,5"], capture_output=True, text=True)
    assert together.returncode == 0, together.stderr
    whole = json.loads((tmp_path / "all.json").read_text())["nested"]["summary"]
    for lv, v in report["nested"]["summary"].items():
        assert v["mean"] == pytest.approx(whole[lv]["mean"]) and v["ci95"] == pytest.approx(whole[lv]["ci95"])
        assert v["total"] == whole[lv]["total"]


@pytest.mark.slow
def test_choose_writes_the_configuration_the_inner_folds_chose(tmp_path):
    from bcc.grounding import nested
    data = pairs_file(tmp_path / "pairs.jsonl")
    out = tmp_path / "votes.json"
    done = subprocess.run([sys.executable, str(ROOT / "bench" / "corpus.py"), "--pairs", str(data), "--choose",
                           "-o", str(out)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    got = json.loads(out.read_text())
    assert got["pool"] == [m for m, _, _ in nested.POOL] and len(got["votes"]) == len(nested.POOL)
    assert got["chosen"] in dict(nested.CONFIGS)
    assert got["inner_accuracy"][got["chosen"]] == max(got["inner_accuracy"].values())
    if got["chosen"] != nested.STACKED:
        assert tuple(got["votes"]) == tuple(float(v) for v in dict(nested.CONFIGS)[got["chosen"]])
    assert "<- chosen" in done.stdout
