"""OpenGL plumbing: shader programs from ``shaders/`` and one-buffer layers rebuilt every frame."""
from __future__ import annotations

import ctypes
import os
from pathlib import Path

import numpy as np
from OpenGL import GL

SHADER_DIR = Path(os.environ.get("STELKROPP_SHADERS", Path(__file__).resolve().parents[2] / "shaders"))

F32 = np.float32


def load_program(name: str) -> int:
    """Compile and link shaders/<name>.vert + shaders/<name>.frag."""
    shaders = []
    for ext, kind in (("vert", GL.GL_VERTEX_SHADER), ("frag", GL.GL_FRAGMENT_SHADER)):
        path = SHADER_DIR / f"{name}.{ext}"
        src = path.read_text()
        sh = GL.glCreateShader(kind)
        GL.glShaderSource(sh, src)
        GL.glCompileShader(sh)
        if not GL.glGetShaderiv(sh, GL.GL_COMPILE_STATUS):
            log = GL.glGetShaderInfoLog(sh).decode(errors="replace")
            raise RuntimeError(f"shader {path} failed to compile:\n{log}")
        shaders.append(sh)
    prog = GL.glCreateProgram()
    for sh in shaders:
        GL.glAttachShader(prog, sh)
    GL.glLinkProgram(prog)
    if not GL.glGetProgramiv(prog, GL.GL_LINK_STATUS):
        log = GL.glGetProgramInfoLog(prog).decode(errors="replace")
        raise RuntimeError(f"shader program {name} failed to link:\n{log}")
    for sh in shaders:
        GL.glDeleteShader(sh)
    return prog


class Layer:
    """One VAO + one VBO with an interleaved float32 layout; rebuilt per frame."""

    def __init__(self, program: int, sizes: list[int], mode=GL.GL_TRIANGLES):
        self.program = program
        self.mode = mode
        self.sizes = sizes
        self.stride = sum(sizes)
        self.vao = GL.glGenVertexArrays(1)
        self.vbo = GL.glGenBuffers(1)
        self.count = 0
        self.capacity = 0
        GL.glBindVertexArray(self.vao)
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, self.vbo)
        off = 0
        for loc, size in enumerate(sizes):
            GL.glEnableVertexAttribArray(loc)
            GL.glVertexAttribPointer(loc, size, GL.GL_FLOAT, GL.GL_FALSE, self.stride * 4, ctypes.c_void_p(off * 4))
            off += size
        GL.glBindVertexArray(0)

    def upload(self, data: np.ndarray) -> None:
        data = np.ascontiguousarray(data, dtype=F32)
        assert data.ndim == 2 and data.shape[1] == self.stride, (data.shape, self.stride)
        self.count = len(data)
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, self.vbo)
        nbytes = data.nbytes
        if nbytes > self.capacity:
            self.capacity = max(nbytes, 2 * self.capacity, 4096)
            GL.glBufferData(GL.GL_ARRAY_BUFFER, self.capacity, None, GL.GL_STREAM_DRAW)
        else:
            GL.glBufferData(GL.GL_ARRAY_BUFFER, self.capacity, None, GL.GL_STREAM_DRAW)  # orphan
        if nbytes:
            GL.glBufferSubData(GL.GL_ARRAY_BUFFER, 0, nbytes, data)

    def draw(self) -> None:
        if self.count:
            GL.glBindVertexArray(self.vao)
            GL.glDrawArrays(self.mode, 0, self.count)
