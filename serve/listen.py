"""The listening socket of `bcc serve`, bound before uvicorn starts.

Why not let uvicorn bind: it logs a port in use or an unknown host and exits 3, which
bcc reserves for its own bugs. Binding here turns both into one line and exit 2, and
`--port 0` can report the port the system picked.
"""
from __future__ import annotations

import socket

from ..errors import BccError


def bind(host: str, port: int) -> socket.socket:
    """A TCP socket bound to HOST:PORT (not yet listening; asyncio's create_server listens)."""
    try:
        family, kind, proto, _, address = socket.getaddrinfo(
            host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)[0]
    except socket.gaierror as exc:
        raise BccError(f"cannot listen on {host}:{port}: {exc.strerror}") from None
    sock = socket.socket(family, kind, proto)
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # restart at once after Ctrl-C
        sock.bind(address)
    except OSError as exc:
        sock.close()
        raise BccError(f"cannot listen on {host}:{port}: {exc.strerror}") from None
    return sock


def url(sock: socket.socket) -> str:
    """http://HOST:PORT/ of a bound socket, IPv6 addresses in brackets."""
    host, port = sock.getsockname()[:2]
    return f"http://[{host}]:{port}/" if ":" in host else f"http://{host}:{port}/"
