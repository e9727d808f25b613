"""tumble: free rigid bodies from particle clouds, from Python.

The C++ layers of tumble (scene reader, core, render pipeline, glTF export)
bound with pybind11: the numbers and pixels are the command line's.

    import tumble
    scene = tumble.Scene.load("scenes/dzhanibekov.toml")
    scene.bodies[0].omega_body = (0.1, 8, 0.1)      # rad/s, the cloud's axes
    run = tumble.simulate(scene, method="splitting", dt=1e-3)
    run[0].t, run[0].omega_body                     # numpy arrays (read-only views)
    tumble.show(scene)                              # in a notebook: the scene as an inline video
"""

from ._tumble import *  # noqa: F401,F403
from ._tumble import __version__  # noqa: F401
from .display import show  # noqa: F401
