"""`bcc minecraft setup`: install the pinned Node packages with `npm ci` (package-lock.json)."""
from __future__ import annotations

import json
import re
import shutil
import subprocess
from typing import Callable

from .bridge import HERE, VERSION, MinecraftError, node_dir, node_executable

PACKAGES = ("flying-squid", "mineflayer", "minecraft-protocol", "minecraft-data")


def node_version(node: str) -> tuple:
    try:
        out = subprocess.run([node, "--version"], capture_output=True, text=True, timeout=20).stdout.strip()
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise MinecraftError(f"cannot run {node}: {exc}") from None
    m = re.match(r"v(\d+)\.(\d+)", out)
    if not m:
        raise MinecraftError(f"{node} --version printed {out!r}, not a Node.js version")
    return int(m.group(1)), int(m.group(2))


def installed_versions() -> dict:
    out = {}
    for name in PACKAGES:
        meta = node_dir() / "node_modules" / name / "package.json"
        if meta.is_file():
            out[name] = json.loads(meta.read_text(encoding="utf-8")).get("version")
    return out


def install(echo: Callable[[str], None] | None = None) -> dict:
    """Run `npm ci` in the package directory; MinecraftError with npm's last words on failure."""
    node = node_executable()
    major, minor = node_version(node)
    if major < 18:
        raise MinecraftError(f"the Minecraft bridge needs Node.js 18 or newer; {node} is {major}.{minor}")
    npm = shutil.which("npm")
    if not npm:
        raise MinecraftError("npm is not on PATH (it comes with Node.js); it installs the Minecraft packages")
    target = node_dir()
    if target != HERE:     # an installed bcc: the pinned manifest goes to the data folder
        try:
            target.mkdir(parents=True, exist_ok=True)
            for name in ("package.json", "package-lock.json"):
                shutil.copyfile(HERE / name, target / name)
        except OSError as exc:
            raise MinecraftError(f"cannot prepare {target} for the Minecraft packages: {exc}") from None
    if echo:
        echo(f"npm ci in {target} ...")
    try:
        proc = subprocess.run([npm, "ci", "--no-audit", "--no-fund"], cwd=str(target), capture_output=True,
                              text=True, timeout=900)
    except subprocess.TimeoutExpired:
        raise MinecraftError("npm ci did not finish within 15 minutes (is the npm registry reachable?)") from None
    if proc.returncode != 0:
        tail = " | ".join(line.strip() for line in (proc.stderr or proc.stdout).strip().splitlines()[-4:])
        raise MinecraftError(f"npm ci failed in {target} (exit {proc.returncode}): {tail}")
    versions = installed_versions()
    missing = [p for p in ("flying-squid", "mineflayer") if p not in versions]
    if missing:
        raise MinecraftError(f"npm ci finished but {missing[0]} is not in {target / 'node_modules'}")
    return {"directory": str(target), "node": f"{major}.{minor}", "packages": versions, "minecraft": VERSION}
