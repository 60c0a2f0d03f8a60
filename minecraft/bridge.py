"""The Python end of the bridge: one long-lived Node process (minecraft/bridge.js) that
runs the flying-squid server and the mineflayer bot, spoken to in JSON lines.

Every request carries an id and waits for its reply with a timeout; a reader thread
routes replies to their callers and queues the server's events (chat, joins), so several
threads may talk to the bridge at once (the recorder polls while a script plays). A dead
or silent Node process is a clear MinecraftError, never a hang.
"""
from __future__ import annotations

import itertools
import json
import os
import queue
import shutil
import subprocess
import tempfile
import threading
from pathlib import Path

from ..errors import BccError

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "bridge.js"
VERSION = "1.16.5"        # the Minecraft protocol version the server speaks (see docs/minecraft.md)
DEFAULT_PORT = 25565
BOT = "bcc_bot"


class MinecraftError(BccError):
    """The Minecraft side failed: Node missing, the bridge died, a request timed out."""


def node_executable() -> str:
    node = os.environ.get("BCC_NODE") or shutil.which("node")
    if not node:
        raise MinecraftError("the Minecraft bridge needs Node.js 18 or newer on PATH (https://nodejs.org), "
                             "then `bcc minecraft setup`")
    return node


def node_dir() -> Path:
    """Where the Node packages live: $BCC_MINECRAFT_DIR; else, in a source checkout, this
    folder (`npm ci` beside package.json); else, for an installed bcc, a data folder
    ($BCC_HOME/minecraft or ~/.local/share/bcc/minecraft), never site-packages."""
    if os.environ.get("BCC_MINECRAFT_DIR"):
        return Path(os.environ["BCC_MINECRAFT_DIR"])
    if not {"site-packages", "dist-packages"} & set(HERE.parts):
        return HERE
    if os.environ.get("BCC_HOME"):
        return Path(os.environ["BCC_HOME"]) / "minecraft"
    base = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
    return Path(base) / "bcc" / "minecraft"


def installed() -> bool:
    modules = node_dir() / "node_modules"
    return (modules / "flying-squid").is_dir() and (modules / "mineflayer").is_dir()


def check_installed() -> None:
    """Node present and the packages installed, else a message saying what to run."""
    node_executable()
    if not installed():
        raise MinecraftError(f"the Minecraft packages are not installed in {node_dir()}: run `bcc minecraft setup`")


class Bridge:
    """A running bridge process. Use as a context manager; `close()` always ends it."""

    def __init__(self, log_path: str | os.PathLike | None = None, timeout: float = 30.0):
        check_installed()
        self.timeout = timeout
        self._ids = itertools.count(1)
        self._pending: dict = {}
        self._lock = threading.Lock()
        self._write_lock = threading.Lock()
        self.events: queue.Queue = queue.Queue()
        self._log_path = Path(log_path) if log_path else None
        self._log = open(self._log_path, "ab") if self._log_path else subprocess.DEVNULL
        self._closed = False
        node = node_executable()
        where = node_dir()
        # Node finds the packages through NODE_PATH; the working folder only has to exist
        # (the data folder does only after `bcc minecraft setup`).
        cwd = where if where.is_dir() else Path(tempfile.gettempdir())
        try:
            env = dict(os.environ, NODE_PATH=str(where / "node_modules"))
            self.proc = subprocess.Popen([node, str(SCRIPT)], cwd=str(cwd), env=env, stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, stderr=self._log, bufsize=0)
        except OSError as exc:
            raise MinecraftError(f"cannot run {node} {SCRIPT} in {cwd}: {exc.strerror or exc}") from None
        self._hello = threading.Event()     # set on the bridge's hello, or when it exits first
        self._started = False
        self._reader = threading.Thread(target=self._read, name="minecraft-bridge-reader", daemon=True)
        self._reader.start()
        self._hello.wait(20)
        if not self._started:
            self.close()
            code = self.proc.poll()
            why = " within 20 s" if code is None else f": it exited with code {code}"
            raise MinecraftError("the Minecraft bridge (node minecraft/bridge.js) did not start" + why
                                 + self._log_tail())

    # -- plumbing ------------------------------------------------------------------------

    def _read(self) -> None:
        for raw in self.proc.stdout:
            try:
                msg = json.loads(raw)
            except ValueError:
                continue  # not ours: the bridge keeps other output on stderr, but be lenient
            if "event" in msg:
                if msg["event"] == "hello":
                    self._started = True
                    self._hello.set()
                else:
                    self.events.put(msg)
                continue
            with self._lock:
                slot = self._pending.get(msg.get("id"))
            if slot is not None:
                slot["reply"] = msg
                slot["done"].set()
        # stdout closed: the process is gone; wake every waiter
        self._hello.set()
        with self._lock:
            for slot in self._pending.values():
                slot["done"].set()
        self.events.put({"event": "exit"})

    def _log_tail(self, lines: int = 5) -> str:
        if not self._log_path or not self._log_path.exists():
            return ""
        tail = self._log_path.read_bytes().decode("utf-8", "replace").strip().splitlines()[-lines:]
        return ("; last lines of " + str(self._log_path) + ": " + " | ".join(t.strip() for t in tail)) if tail else ""

    def exit_error(self) -> MinecraftError:
        """The error for a bridge whose Node process has exited (its status and the log's last lines)."""
        try:
            code = self.proc.wait(2)      # its stdout closed: the exit status follows at once
        except subprocess.TimeoutExpired:
            code = None
        return MinecraftError(f"the Minecraft bridge (node) exited{'' if code is None else f' with code {code}'}"
                              + self._log_tail())

    def request(self, op: str, timeout: float | None = None, **args):
        """Send one request and wait for its result; MinecraftError on error, timeout or death."""
        if self._closed or self.proc.poll() is not None:
            raise self.exit_error()
        rid = next(self._ids)
        slot = {"done": threading.Event(), "reply": None}
        with self._lock:
            self._pending[rid] = slot
        line = (json.dumps({"id": rid, "op": op, **args}) + "\n").encode()
        try:
            with self._write_lock:
                self.proc.stdin.write(line)
                self.proc.stdin.flush()
        except (BrokenPipeError, OSError):
            with self._lock:
                self._pending.pop(rid, None)
            raise self.exit_error() from None
        wait = self.timeout if timeout is None else timeout
        finished = slot["done"].wait(wait)
        with self._lock:
            self._pending.pop(rid, None)
        reply = slot["reply"]
        if reply is None:
            if not finished:
                raise MinecraftError(f"the Minecraft bridge did not answer '{op}' within {wait:g} s" + self._log_tail())
            raise self.exit_error()
        if not reply.get("ok"):
            raise MinecraftError(f"Minecraft bridge: {op}: {reply.get('error')}")
        return reply.get("result")

    def next_event(self, timeout: float) -> dict | None:
        try:
            return self.events.get(timeout=timeout)
        except queue.Empty:
            return None

    # -- the operations (see bridge.js) ------------------------------------------------

    def start(self, port: int = DEFAULT_PORT, version: str = VERSION, host: str = "127.0.0.1") -> dict:
        return self.request("start", port=port, version=version, host=host, timeout=40)

    def build(self, world_map, state: bytes | None = None) -> dict:
        """Build the dungeon block by block at the map's origin: its start, or `state`."""
        x, y, z = world_map.model.agent_position(world_map.model.initial)
        return self.request("build", origin=list(world_map.origin), size=list(world_map.size),
                            blocks=world_map.blocks(state), mineable=world_map.mineable(), spawn=[x, y, z],
                            timeout=60)

    def build_state(self, world_map, state: bytes) -> dict:
        return self.build(world_map, state)

    def spawn_bot(self, username: str = BOT, person: bool = False) -> dict:
        """Bring a mineflayer bot into the world; `person=True` makes the bridge treat it as a
        person (set up by the server, recorded like a player): tests play a human with it."""
        return self.request("spawn_bot", username=username, person=person, timeout=40)

    def setup(self, player: str | None, pose: dict, hotbar: list | None, inventory: list | None = None) -> dict:
        """Put a player into a cell with a view, a hotbar, and (for a model that counts
        carried blocks) `inventory`: [[item, total], ...] spread over its 36 slots."""
        return self.request("setup", player=player, position=pose["position"], yaw=pose["yaw"],
                            pitch=pose["pitch"], selected=pose["selected"], hotbar=hotbar, inventory=inventory)

    def observe(self, player: str | None = None, blocks: bool = True) -> dict:
        return self.request("observe", player=player, blocks=blocks)

    def act(self, player: str, **geometry) -> dict:
        return self.request("act", player=player, timeout=25, **geometry)

    def players(self) -> list:
        return self.request("players")["players"]

    def chat(self, text: str, player: str | None = None) -> None:
        self.request("chat", text=text, player=player)

    def say(self, player: str, text: str) -> None:
        """Make a bot type `text` in the chat, as a person would."""
        self.request("say", player=player, text=text)

    def close(self) -> None:
        """Stop the server and the process: politely, then by force; never blocks for long."""
        if self._closed:
            return
        if self.proc.poll() is None:
            try:
                self.request("stop", timeout=5)
            except MinecraftError:
                pass
        self._closed = True
        try:
            self.proc.stdin.close()
        except OSError:
            pass
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait(5)
        if self._log is not subprocess.DEVNULL:
            self._log.close()

    def __enter__(self) -> "Bridge":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

