"""Refuse request bodies over a size limit with 413, without reading past the limit.

A declared Content-Length over the limit is refused at once; a chunked body is counted
as it arrives; past the limit the rest is not read and the answer is a 413.
"""
from __future__ import annotations

import json


class BodyLimit:
    """ASGI middleware: at most `max_bytes` of request body."""

    def __init__(self, app, max_bytes: int):
        self.app, self.max_bytes = app, max_bytes

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        length = dict(scope.get("headers") or []).get(b"content-length")
        if length is not None and length.isdigit() and int(length) > self.max_bytes:
            return await self._refuse(send)
        seen = 0
        too_large = False
        replaced = False

        async def counted_receive():
            # Past the limit the app is told the body has ended, and whatever it answers
            # (FastAPI turns a failing body read into a 400) is replaced by the 413.
            nonlocal seen, too_large
            if too_large:
                return {"type": "http.request", "body": b"", "more_body": False}
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.max_bytes:
                    too_large = True
                    return {"type": "http.request", "body": b"", "more_body": False}
            return message

        async def guarded_send(message):
            nonlocal replaced
            if not too_large:
                return await send(message)
            if not replaced:
                replaced = True
                await self._refuse(send)

        await self.app(scope, counted_receive, guarded_send)

    async def _refuse(self, send):
        body = json.dumps({"error": f"the request body is over the limit of {self.max_bytes} bytes",
                           "line": None, "column": None, "file": None}).encode()
        await send({"type": "http.response.start", "status": 413,
                    "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode()),
                                (b"connection", b"close")]})
        await send({"type": "http.response.body", "body": body})
