"""CLI for the grounding layer: `bcc play`, `learn`, `train`, `command`, `corpus`.

Heavy work (compiling, EM, SQLite) is imported inside each command, so `bcc --help`
stays fast.
"""
from __future__ import annotations

import json
import sys
from collections import Counter

import click

from .shared import (budget_options, clear_progress, compile_model, emit_json, json_option, max_memory_option,
                          print_result, progress_enabled, time_limit_option, within_budget)
from ..exit_codes import EXIT_NO_SOLUTION, EXIT_OK
from ..errors import BccError

db_option = click.option("--db", "db", type=click.Path(dir_okay=False), default=None,
                         help="The dataset file [default: $BCC_HOME/grounding.sqlite or ~/.local/share/bcc/grounding.sqlite].")


@click.command("play")
@click.argument("dungeon")
@click.option("--record", type=click.Path(dir_okay=False, writable=True), help="Save the session as a demonstration (JSON, atomically).")
@click.option("--command", "command_text", default=None, help="The command the session carries out (stored in the demonstration).")
@json_option
def play_cmd(dungeon, record, command_text, as_json):
    """Play DUNGEON in the terminal: one key per action, the map redrawn each step, q quits.

    On a terminal keys act at once; from a pipe each line is a string of keys."""
    from ..atomic import check_writable
    from ..demonstration import extract
    from ..grounding.play import line_keys, play, tty_keys
    model = compile_model(dungeon, None)
    if record:
        check_writable(record)   # before the session, not after it
    interactive = sys.stdin.isatty() and sys.stdout.isatty() and not as_json
    keys = tty_keys() if interactive else line_keys(sys.stdin)
    out = (lambda text: click.echo(text, err=True)) if as_json else click.echo
    states = play(model, keys, out, clear=interactive)
    demo = extract(model, states)
    demo.command = command_text
    if record and demo.dungeon == model.path:   # a dungeon file: name it relative to the recording
        import os
        demo.dungeon = os.path.relpath(os.path.abspath(model.path), os.path.dirname(os.path.abspath(record)))
    if record:
        demo.save(record)
    if as_json:
        emit_json({"dungeon": model.name, "actions": demo.actions, "steps": len(demo.actions),
                   "goal_reached": model.is_goal(demo.states[-1]), "recorded": record})
    else:
        click.echo(f"{len(demo.actions)} action(s)" + (f"; demonstration saved to {record}" if record else ""))


@click.command("learn")
@click.argument("dungeon")
@click.argument("command_text", metavar="COMMAND")
@click.option("--demo", "demo_path", required=True, type=click.Path(dir_okay=False), help="A demonstration file (see `bcc play --record`).")
@db_option
@budget_options
@json_option
def learn_cmd(dungeon, command_text, demo_path, db, time_limit, max_memory, as_json):
    """Add a (COMMAND, demonstration) pair in DUNGEON to the dataset, with its inferred task."""
    from ..grounding.learn import add_pair
    with within_budget(time_limit, max_memory, as_json, dungeon):
        added = add_pair(dungeon, command_text, demo_path, db)
    if as_json:
        emit_json(added)
        return
    click.echo(f"pair {added['id']} added to {added['db']} ({added['pairs']} pair(s)): "
               f"{command_text!r} -> {added['task']}")
    for e in added["explanations"][1:]:
        click.echo(f"  also explains: {e['task']} (weight {e['weight']:.3g})")


@click.command("train")
@db_option
@click.option("--corpus/--no-corpus", "with_corpus", default=False, show_default=True,
              help="Also train on the shipped corpus's training split.")
@click.option("--pairs", "pairs_paths", multiple=True, type=click.Path(dir_okay=False),
              help="Also train on command/task pairs without demonstrations (JSON Lines, see `bcc corpus evaluate`); repeatable.")
@click.option("--dungeon", default=None, help="The dungeon of --pairs lines that name none.")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Also write the model to FILE (JSON, atomically).")
@budget_options
@json_option
def train_cmd(db, with_corpus, pairs_paths, dungeon, output, time_limit, max_memory, as_json):
    """Retrain the grounding model on the dataset (and --corpus, --pairs); store it there."""
    from ..grounding.dataset import default_path
    with within_budget(time_limit, max_memory, as_json, str(db or default_path())):
        _train(db, with_corpus, pairs_paths, dungeon, output, as_json)


def _train(db, with_corpus, pairs_paths, dungeon, output, as_json):
    from ..grounding import corpus, pairs, task_pairs
    from ..grounding.dataset import Dataset
    from ..grounding.learn import candidates, train
    rows, task_rows = [], []
    for path in pairs_paths:
        given = pairs.load(path, dungeon)
        _say_inferred(path, given)
        calls = [r for r in given if task_pairs.is_task_row(r)]   # a dungeon with tasks: task calls
        goals = [r for r in given if r not in calls]
        task_pairs.check(calls)
        pairs.check_tasks(goals)
        task_rows += calls
        rows += [{"command": r["command"], "dungeon": r["dungeon"], "explanations": [{"task": r["task"], "weight": 1.0}]}
                 for r in goals]
    if task_rows and with_corpus:
        task_rows += task_pairs.shipped_rows()
    if output:
        from ..atomic import check_writable
        check_writable(output)
    data = Dataset(db)
    model = task_model = None
    try:
        rows = data.pairs() + rows
        if with_corpus:
            rows += [r | {"dungeon": corpus.resolve(r["dungeon"])} for r in corpus.load() if r["split"] == "train"]
        if not rows and not task_rows:
            raise BccError("the dataset has no pairs: add some with `bcc learn`, or pass --corpus or --pairs FILE",
                           str(data.path))
        if output and rows and task_rows:
            raise BccError("-o writes one model: train goal pairs and task-call pairs apart")
        if rows:
            model, seconds = train(rows, candidates_of=lambda r: corpus.candidates(r) if "prefix" in r
                                   else candidates(r["dungeon"]))
            data.add_model(model.to_json(), len(rows), with_corpus, seconds)
        if task_rows:
            task_model, task_seconds = task_pairs.train(task_rows)
            data.add_model(task_model.to_json(), len(task_rows), with_corpus, task_seconds)
    finally:
        data.close()
    if output:
        (model or task_model).save(output)
    report = {"db": str(data.path), "output": output, "with_corpus": with_corpus}
    if model is not None:
        report |= {"pairs": len(rows), "vocabulary": len(model.vocabulary), "iterations": model.iterations,
                   "seconds": round(seconds, 3)}
    if task_model is not None:
        report |= {"task_pairs": len(task_rows), "task_vocabulary": len(task_model.speller.counts),
                   "task_seconds": round(task_seconds, 3)}
    if as_json:
        emit_json(report)
        return
    if model is not None:
        click.echo(f"trained on {len(rows)} pair(s), {len(model.vocabulary)} words, {model.iterations} iterations "
                   f"in {seconds:.2f} s; stored in {data.path}")
        if not with_corpus:
            trained = sorted({r["dungeon"] for r in rows})
            click.echo(f"note: this model replaces the shipped one and knows commands for {', '.join(trained)} only; "
                       f"--corpus also trains on the shipped corpus (the other dungeons)", err=True)
    if task_model is not None:
        click.echo(f"trained a task-call model on {len(task_rows)} pair(s) "
                   f"({', '.join(sorted({r['dungeon'] for r in task_rows}))}) in {task_seconds:.2f} s; "
                   f"stored in {data.path}")


def _translation(db, model_path):
    """The model `bcc command` uses: --model FILE, else the dataset's newest, else the corpus's."""
    from pathlib import Path

    from ..grounding.dataset import Dataset, default_path
    from ..grounding.models import GOAL_FORMATS, from_json, load
    if model_path:
        model = load(model_path)
        if type(model).__name__ == "TaskCallModel":
            raise BccError("this is a task-call model: it commands a dungeon whose domain has tasks", model_path)
        return model, model_path
    path = Path(db) if db else default_path()
    if path.is_file():
        data = Dataset(path)
        try:
            latest = data.latest_model(GOAL_FORMATS)
        finally:
            data.close()
        if latest is not None:
            return from_json(latest, str(path)), str(path)
    from ..grounding import corpus
    return corpus.corpus_model(), "shipped corpus"


def _task_model(db, model_path):
    """The task-call model of a dungeon with tasks: --model FILE, else the dataset's newest
    task-call model, else the one trained on the shipped task pairs."""
    from pathlib import Path

    from ..grounding import task_pairs
    from ..grounding.dataset import Dataset, default_path
    from ..grounding.models import from_json, load
    from ..grounding.task_model import FORMAT, TaskCallModel
    if model_path:
        model = load(model_path)
        if not isinstance(model, TaskCallModel):
            raise BccError("this is a goal model; a dungeon whose domain has tasks is commanded by a task-call "
                           "model (bcc train --pairs FILE of task calls -o FILE)", model_path)
        return model, model_path
    path = Path(db) if db else default_path()
    if path.is_file():
        data = Dataset(path)
        try:
            latest = data.latest_model((FORMAT,))
        finally:
            data.close()
        if latest is not None:
            return from_json(latest, str(path)), str(path)
    return task_pairs.shipped_model(), "shipped task pairs"


@click.command("command")
@click.argument("dungeon")
@click.argument("text", metavar="TEXT")
@db_option
@click.option("--model", "model_path", type=click.Path(dir_okay=False), help="Use this model file (from `bcc train -o`).")
@time_limit_option("Stop after this many seconds (compiling, interpreting and planning together).",
                   default=60, show_default=True)
@max_memory_option()
@json_option
def command_cmd(dungeon, text, db, model_path, time_limit, max_memory, as_json):
    """Interpret a natural-language command in DUNGEON and plan it.

    In a dungeon whose domain has tasks the command becomes a task call, planned by htn
    ("build a 3 by 4 wall of stone" -> wall(1, 1, 3, 4, stone)); elsewhere a goal, planned
    by A*. Exit 0 when the chosen task is solved; 1 when none is plausible, it has no plan
    or a budget ran out."""
    from ..solvers.limits import Deadline
    from ..grounding.calls import space_for as call_space
    if not text.strip():
        raise BccError("the command is empty")
    with within_budget(time_limit, max_memory, as_json, dungeon, grace=None) as budget:
        deadline = Deadline(budget)
        calls = call_space(dungeon)      # the front end only: a dungeon with tasks is commanded by them
        if calls:
            found, name, where, source = _command_task(dungeon, text, calls, db, model_path, deadline)
        else:
            found, name, where, source = _command_goal(dungeon, text, db, model_path, deadline)
    ok = found.result is not None and found.result.solved
    if as_json:
        emit_json({"dungeon": name, **found.to_json(), "model": source})
        sys.exit(EXIT_OK if ok else EXIT_NO_SOLUTION)
    def say(line):   # the plan alone goes to stdout, as with `bcc solve`
        click.echo(line, err=True)
    if found.task is None:
        say(f"not understood: {found.message}" +
            (f" (unknown words: {', '.join(found.unknown_words)})" if found.unknown_words else ""))
        sys.exit(EXIT_NO_SOLUTION)
    say(f"task: {found.task}")
    say("candidates:")
    for t, s in found.candidates:
        say(f"  {s:8.4f}  {t}")
    if found.unknown_words:
        say(f"unknown words (ignored): {', '.join(found.unknown_words)}")
    sys.exit(print_result(found.result, name, where, False))


def _command_goal(dungeon, text, db, model_path, deadline):
    """A goal of the dungeon (grounding/tasks.py's candidates), planned by A*."""
    from ..grounding.interpret import plan, rank
    from ..grounding.learn import space_for
    model = compile_model(dungeon, None)
    translation, source = _translation(db, model_path)   # may train a model: counted too
    space = space_for(dungeon)
    found = rank(translation, space, model.initial, text, unseen_names_refused=True)
    if found.task is not None:
        found.result = plan(dungeon, found.task, None, deadline.remaining())
        if not found.result.solved:
            found.message = f"no plan for {found.task}: {found.result.message}"
    return found, model.name, model.path, source


def _command_task(dungeon, text, calls, db, model_path, deadline):
    """A call of one of the domain's tasks (grounding/calls.py), planned by htn through the
    run path `bcc solve` takes."""
    from ..run import Request, run
    model, source = _task_model(db, model_path)
    found = model.interpret(text, calls)
    where = dungeon
    if found.task is not None:
        ran = run(Request(lambda: compile_model(dungeon, None, found.task), "htn", budget=deadline.remaining(),
                          hard=False))
        found.result = ran.result
        where = ran.model.path if ran.model is not None else dungeon
        if not found.result.solved:
            found.message = f"no plan for {found.task}: {found.result.message}"
    return found, calls.name, where, source


@click.group("corpus")
def corpus_group():
    """The shipped command/demonstration corpus."""


@corpus_group.command("generate")
@click.option("--pairs", type=click.IntRange(min=10), default=360, show_default=True)
@click.option("--seed", type=int, default=0, show_default=True)
@click.option("--workers", type=click.IntRange(min=1), default=1, show_default=True,
              help="Plan demonstrations on this many processes (through the batch API); "
                   "the output is the same for any number.")
@json_option
def corpus_generate_cmd(pairs, seed, workers, as_json):
    """Rebuild grounding/corpus/ (dungeons and pairs.jsonl) with a fixed seed (takes minutes)."""
    from ..grounding import corpus
    show = progress_enabled()
    progress = (lambda k, n: click.echo(f"\r  {k}/{n}", err=True, nl=False)) if show else None
    stats = corpus.generate(pairs, seed, workers=workers, progress=progress)
    if show:
        click.echo("", err=True)
    if as_json:
        emit_json(stats)
    else:
        click.echo(json.dumps(stats, indent=2))


@corpus_group.command("evaluate")
@click.option("--train", "train_path", type=click.Path(dir_okay=False), default=None,
              help="Pairs to train on (JSON Lines with command and task); without it, the shipped corpus's split.")
@click.option("--test", "test_path", type=click.Path(dir_okay=False), default=None,
              help="Pairs to test on [default: --folds cross-validation over --train].")
@click.option("--folds", type=click.IntRange(min=2), default=None, help="K-fold cross-validation over --train [default: 10].")
@click.option("--dungeon", default=None, help="The dungeon of pairs that name none.")
@click.option("--level", "levels", multiple=True, help="Only pairs of this level (repeatable).")
@click.option("--from", "mode", type=click.Choice(["tasks", "demonstrations", "both"]), default="both", show_default=True,
              help="Train on the given tasks, on tasks inferred from planned demonstrations, or report both.")
@click.option("--seed", type=int, default=0, show_default=True, help="Seed of the fold shuffle.")
@click.option("--shuffles", type=click.IntRange(min=1), default=1, show_default=True,
              help="Cross-validate this many shuffles (seeds --seed, --seed + 1, ...); report each, their mean, "
                   "spread and a 95% interval per level.")
@click.option("--nested", is_flag=True,
              help="Choose each fold's votes by a 3-fold cross-validation inside its training pairs (nested).")
@click.option("--workers", type=click.IntRange(min=1), default=1, show_default=True,
              help="Train the folds' models on this many processes at once (each under an equal share "
                   "of --max-memory); the report is the same for any number.")
@budget_options
@json_option
def corpus_evaluate_cmd(train_path, test_path, folds, dungeon, levels, mode, seed, shuffles, nested, workers,
                        time_limit, max_memory, as_json):
    """Train a fresh model on training pairs only; report held-out accuracy overall, per level,
    and a confusion table of tasks.

    Without --train: the shipped corpus's training split and held-out split."""
    with within_budget(time_limit, max_memory, as_json, train_path or "corpus") as budget:
        _evaluate(train_path, test_path, folds, dungeon, levels, mode, seed, as_json, workers, budget.max_memory_mb,
                  shuffles, nested)


def _evaluate(train_path, test_path, folds, dungeon, levels, mode, seed, as_json, workers=1, memory_mb=None,
              shuffles=1, nested=False):
    if train_path is None:
        if test_path or folds or dungeon or levels or workers > 1 or shuffles > 1 or nested:
            raise BccError("--test, --folds, --dungeon, --level, --shuffles, --nested and --workers need --train FILE")
        return _evaluate_shipped(as_json)
    from ..grounding import pairs
    from ..grounding.shuffles import summarise
    if test_path and folds:
        raise BccError("give --test FILE or --folds K, not both")
    if test_path and shuffles > 1:
        raise BccError("--shuffles needs cross-validation: give --folds K, not --test FILE")
    train_rows = pairs.load(train_path, dungeon, levels)
    _say_inferred(train_path, train_rows)
    test_rows = pairs.load(test_path, dungeon, levels) if test_path else None
    if test_rows:
        _say_inferred(test_path, test_rows)
    from ..grounding import task_pairs
    calls = [r for r in train_rows + (test_rows or []) if task_pairs.is_task_row(r)]
    if calls:
        if len(calls) != len(train_rows) + len(test_rows or []):
            raise BccError("the pairs mix goals and task calls (dungeons with tasks): evaluate them apart")
        if mode == "demonstrations" or shuffles > 1 or nested or workers > 1:
            raise BccError("task-call pairs are evaluated from their calls: --from demonstrations, --shuffles, "
                           "--nested and --workers are for goals")
        return _evaluate_task_calls(train_rows, test_rows, folds, seed, as_json, train_path, test_path)
    pairs.check_tasks(train_rows + (test_rows or []))
    seeds = [seed + k for k in range(shuffles)]
    modes = list(pairs.MODES) if mode == "both" else [mode]
    runs = {m: [] for m in modes}       # mode -> one report per shuffle
    for s in seeds:
        splits = [(train_rows, test_rows)] if test_rows else pairs.folds(train_rows, folds or 10, s)
        for m in modes:
            runs[m].append(pairs.evaluate(splits, m, _fold_progress(m), workers, memory_mb, s if nested else None))
    clear_progress(progress_enabled())
    reports = [runs[m][0] | ({"shuffles": [{"seed": s, "accuracy": r["accuracy"], "by_level": r["by_level"]}
                                           | ({"chosen": r["chosen"]} if nested else {})
                                           for s, r in zip(seeds, runs[m])],
                              "summary": summarise(runs[m])} if shuffles > 1 else {}) for m in modes]
    if as_json:
        emit_json(reports[0] if len(reports) == 1 else {**reports[0], "modes": {r["mode"]: r for r in reports}})
        return
    how = f"train on {train_path}, test on {test_path}" if test_rows else \
        f"{folds or 10}-fold cross-validation over {train_path}" + (f", {shuffles} shuffles" if shuffles > 1 else "")
    click.echo(f"{len(train_rows) + len(test_rows or [])} pairs; {how}" + ("; votes chosen by nested 3-fold" if nested else ""))
    for r in reports:
        if shuffles > 1:
            click.echo(f"from {r['mode']}: mean of {shuffles} shuffles, lowest-highest, 95% interval (Wilson)")
            for level, v in r["summary"].items():
                click.echo(f"  {level:>6}  {v['mean']:.1%}  {v['low']:.1%}-{v['high']:.1%}  "
                           f"[{v['ci95'][0]:.1%}, {v['ci95'][1]:.1%}]  of {v['total']}")
            continue
        click.echo(f"from {r['mode']}: accuracy {r['accuracy']:.1%} (training {r['train_seconds']:.1f} s a model)")
        for level, v in r["by_level"].items():
            click.echo(f"  {level:>6}  {v['correct']:5d}/{v['total']:<5d} {v['accuracy']:.1%}")
    if nested:
        chosen = Counter(c["config"] for r in reports for one in runs[r["mode"]] for c in one["chosen"])
        click.echo("votes chosen by the inner cross-validations: "
                   + ", ".join(f"{name} {n}" for name, n in chosen.most_common()))
    click.echo(f"confusion (from {reports[0]['mode']}{', first shuffle' if shuffles > 1 else ''}): task -> predicted, count")
    for c in reports[0]["confusion"]:
        click.echo(f"  {'ok ' if c['task'] == c['predicted'] else '   '}{c['count']:5d}  {c['task']}  ->  {c['predicted']}")


def _evaluate_task_calls(train_rows, test_rows, folds, seed, as_json, train_path, test_path):
    """Task-call pairs: exact-call accuracy (the task and every argument), per kind of command."""
    from ..grounding import task_pairs
    task_pairs.check(train_rows + (test_rows or []))
    if test_rows:
        model, seconds = task_pairs.train(train_rows)
        report = task_pairs.evaluate(model, test_rows) | {"train_seconds": round(seconds, 3)}
        how = f"train on {train_path}, test on {test_path}"
    else:
        report = task_pairs.cross_validate(train_rows, folds or 10, seed)
        how = f"{folds or 10}-fold cross-validation over {train_path}"
    report |= {"mode": "tasks", "kind": "task calls"}
    if as_json:
        emit_json(report)
        return
    click.echo(f"{len(train_rows) + len(test_rows or [])} task-call pairs; {how}")
    click.echo(f"accuracy (the same call) {report['correct']}/{report['total']} = {report['accuracy']:.1%} "
               f"(training {report['train_seconds']:.2f} s a model)")
    for kind, v in report["by_kind"].items():
        click.echo(f"  {kind:>10}  {v['correct']:4d}/{v['total']:<4d} {v['accuracy']:.1%}")
    for p in report["pairs"]:
        if not p["correct"]:
            click.echo(f"  {p['command']!r} -> {p['predicted'] or 'not understood'} (expected {p['task']})")


def _fold_progress(mode: str):
    """On a terminal, a line on stderr per model trained (ten folds of two modes take minutes)."""
    if not progress_enabled():
        return None
    return lambda k, n: click.echo(f"\r  from {mode}: {k}/{n} models trained", err=True, nl=False)


def _say_inferred(path, rows) -> None:
    """A note on stderr where pairs name no dungeon and bcc chose one from their tasks."""
    chosen = sorted({r["dungeon"] for r in rows if r.get("inferred")})
    if chosen:
        click.echo(f"{path}: pairs with no dungeon are read in {chosen[0]!r}, the shipped dungeon that has "
                   f"all their tasks (--dungeon chooses another)", err=True)


def _evaluate_shipped(as_json):
    """The shipped corpus: train on its training split, report accuracy on its held-out split."""
    import time

    from ..grounding import corpus
    rows = corpus.load()
    train_rows = [r for r in rows if r["split"] == "train"]
    test_rows = [r for r in rows if r["split"] == "test"]
    model, seconds = corpus.train(train_rows)
    t0 = time.perf_counter()
    result = corpus.evaluate(model, test_rows)
    report = {"pairs": len(rows), "train": len(train_rows), "test": len(test_rows),
              "train_seconds": round(seconds, 3), "evaluate_seconds": round(time.perf_counter() - t0, 3),
              "inferred_top_is_true_task": sum(r["explanations"][0]["task"] == r["task"] for r in rows) / len(rows),
              **{k: result[k] for k in ("correct", "accuracy", "errors")}}
    if as_json:
        emit_json(report)
        return
    click.echo(f"corpus: {len(rows)} pairs ({len(train_rows)} train, {len(test_rows)} held out); "
               f"trained in {seconds:.2f} s")
    click.echo(f"held-out accuracy: {result['correct']}/{len(test_rows)} = {result['accuracy']:.1%}")
    for e in result["errors"]:
        click.echo(f"  {e['dungeon']}: {e['command']!r} -> {e['got']} (expected {e['task']})")


COMMANDS = [play_cmd, learn_cmd, train_cmd, command_cmd, corpus_group]
