"""Stelkropp sandbox (pyglet + OpenGL 3.3 core + imgui-bundle); talks to physics only through its public API."""
