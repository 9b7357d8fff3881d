"""A quiet local HTTP server for a built site (127.0.0.1 only), in a background thread."""
from __future__ import annotations

import contextlib
import functools
import http.server
import threading
from pathlib import Path


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):  # noqa: A002 (the base class's name)
        pass


@contextlib.contextmanager
def serving(root: Path, port: int = 0):
    """Serve ``root`` on http://127.0.0.1:PORT/ while the block runs; yields the base URL.
    Port 0 takes a free one."""
    handler = functools.partial(_Quiet, directory=str(root))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", port), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    finally:
        httpd.shutdown()
        httpd.server_close()
        thread.join(5)


def serve_forever(root: Path, port: int) -> None:
    """Serve ``root`` until Ctrl+C."""
    with serving(root, port) as url:
        print(f"serving {root} at {url} (Ctrl+C stops)")
        try:
            threading.Event().wait()
        except KeyboardInterrupt:
            pass
