"""framedyn from Python: meshes, modes, static response, rainflow counting, studies run in memory (issue 20).

The functions are those of the framedyn program, computed by the same C++
libraries (the extension _framedyn links them), and return numpy arrays in the
input's units; each result has a ``units`` dict. Bad input raises
framedyn.Error (a RuntimeError) with framedyn's own message and its ``file``,
``line`` and ``key``. The solvers release the GIL. docs/user-guide.md, "Python".
"""
from . import _build


def _cpu_flags():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return None


def _check_processor():
    # The extension is compiled for the build machine's vector units
    # (-march=native): on a processor without them it would stop with SIGILL.
    have = _cpu_flags()
    if have is None:
        return
    missing = [f for f in _build.cpu_features if f not in have]
    if missing:
        raise ImportError(
            "framedyn: this copy was built with '%s' (%s) for a processor with %s; this processor lacks %s. "
            "Rebuild framedyn on this machine (or configure with -DFRAMEDYN_NATIVE=OFF for a portable build)."
            % (_build.flags, _build.compiler, ", ".join(_build.cpu_features), ", ".join(missing)))


_check_processor()

from ._framedyn import (  # noqa: E402  (after the processor check, on purpose)
    Error, Mesh, ModesResult, StaticResult, RainflowResult, Study, Results, build_signature, read_mesh, modes, static,
    rainflow, load_study, batch)

__all__ = ["Error", "Mesh", "ModesResult", "StaticResult", "RainflowResult", "Study", "Results", "build_signature",
           "read_mesh", "modes", "static", "rainflow", "load_study", "batch"]
