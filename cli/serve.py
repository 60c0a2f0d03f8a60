"""`bcc serve`: run the HTTP service (needs the `serve` extra: FastAPI and uvicorn)."""
from __future__ import annotations

import os
import sys

import click

from .shared import emit_json, json_option


@click.command("serve")
@click.option("--host", default="127.0.0.1", show_default=True, help="Address to listen on.")
@click.option("--port", type=click.IntRange(0, 65535), default=8765, show_default=True)
@click.option("--workers", type=click.IntRange(min=1), default=None,
              help="Solves that run at once; more wait in a queue [default: the number of CPUs].")
@click.option("--max-body", "max_body_kb", type=click.IntRange(min=1), default=1000, show_default=True,
              metavar="KB", help="Larger request bodies get 413.")
@click.option("--job-memory", "job_memory_mb", type=click.FloatRange(min=16), default=1024, show_default=True,
              metavar="MB", help="Memory a job may add to its process (default and cap of max_memory_mb).")
@click.option("--max-time-limit", type=click.FloatRange(min=0, min_open=True), default=300, show_default=True,
              metavar="SECONDS", help="Cap on a solve's time_limit.")
@json_option
def serve_cmd(host, port, workers, max_body_kb, job_memory_mb, max_time_limit, as_json):
    """Serve the JSON API and the web viewer (open http://HOST:PORT/).

    \b
    Examples:
      bcc serve                         # http://127.0.0.1:8765/
      bcc serve --port 9000 --workers 4
      bcc serve --port 0 --json         # any free port; prints {"url": ...} once listening
    """
    try:
        import uvicorn
        from ..serve.app import Settings, create_app
    except ImportError as exc:
        from ..extras import missing
        raise missing("bcc serve", exc.name, "serve") from None
    settings = Settings(workers=workers or os.cpu_count() or 1, max_body_bytes=max_body_kb * 1000,
                        job_memory_mb=job_memory_mb, max_time_limit=max_time_limit)
    from ..serve.listen import bind, url
    sock = bind(host, port)
    if as_json:
        emit_json({"url": url(sock), "port": sock.getsockname()[1], "workers": settings.workers,
                   "max_body_bytes": settings.max_body_bytes, "job_memory_mb": job_memory_mb,
                   "max_time_limit": max_time_limit})
        sys.stdout.flush()
    click.echo(f"bcc serve: {url(sock)} ({settings.workers} worker(s); Ctrl-C stops)", err=True)
    server = uvicorn.Server(uvicorn.Config(create_app(settings), log_level="warning"))
    with sock:
        server.run(sockets=[sock])


COMMANDS = [serve_cmd]
