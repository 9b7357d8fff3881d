"""The scene renderer (OpenGL 3.3 core, shaders in ``shaders/``) and what it is told to draw."""
from .decor import Decor, Overlays
from .renderer import Renderer

__all__ = ["Decor", "Overlays", "Renderer"]
