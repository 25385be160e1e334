"""`pip install --no-index --no-build-isolation .` from the repository root:
the same package as ./python (python/setup.py says how it is built)."""
import os
import runpy

runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)), "python", "setup.py"), run_name="__main__")
