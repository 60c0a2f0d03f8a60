"""What the live Minecraft tests share: skip (saying why) where Node or the Node packages
are missing, a free port, and a bridge that always closes its server."""
from __future__ import annotations

import shutil

import pytest

from bcc.minecraft.bridge import Bridge, installed, node_dir
from serve_harness import free_port

__all__ = ["free_port", "open_bridge", "require_minecraft"]


def require_minecraft() -> None:
    """Skip the calling test module unless a Minecraft server can run here."""
    if not shutil.which("node"):
        pytest.skip("Node.js is not installed: the Minecraft server cannot run", allow_module_level=True)
    if not installed():
        pytest.skip(f"the Minecraft packages are not installed in {node_dir()}: run `bcc minecraft setup`",
                    allow_module_level=True)


def open_bridge(tmp_path):
    """The body of a test module's `bridge` fixture: `yield from open_bridge(tmp_path)`."""
    b = Bridge(log_path=tmp_path / "bridge.log", timeout=30)
    try:
        yield b
    finally:
        b.close()
