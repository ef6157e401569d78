"""setuptools' half of pyproject.toml: builds exidel's compiled module and command with
CMake and puts them in the package.

    python3 -m venv --system-site-packages V && V/bin/pip install --no-build-isolation .
    pip wheel --no-build-isolation --no-deps .

The package gets exidel/_core (the module), exidel/bin/exidel (the command, which
exidel._paths.cli names relative to the package, wherever it is installed) and a copy of the
command in the environment's bin/ (pip's data scheme), where `cmake --install` puts it too.

The CMake tree: by default build/pip/temp.*/cmake (setuptools' build directory), configured
once (Release; tests, benchmarks and install rules off) and rebuilt incrementally by the
next install. Environment:

    EXIDEL_CMAKE_BUILD_DIR  an existing, configured exidel build tree to package instead (only
                            the targets exidel_python and exidel_cli are built there)
    CMAKE_ARGS              more arguments for the configure step
                            (-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    CMAKE_BUILD_PARALLEL_LEVEL  parallel jobs of the build (CMake's own variable)
    EXIDEL_SETUP_BUILD_BASE setuptools' build directory (default: build/pip in the source tree)
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
TARGETS = ["exidel_python", "exidel_cli"]


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(exidel\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)", text)
    if not match:
        raise RuntimeError("setup.py: no project(exidel VERSION x.y.z) in CMakeLists.txt")
    return match.group(1)


def run(command):
    print("setup.py:", shlex.join(command), flush=True)
    subprocess.run(command, check=True)


class CMakeBuild(build_ext):
    """Builds exidel._core with CMake instead of compiling sources itself."""

    def build_extension(self, ext):
        tree = os.environ.get("EXIDEL_CMAKE_BUILD_DIR")
        if tree:
            build = Path(tree).resolve()
            if not (build / "CMakeCache.txt").is_file():
                raise RuntimeError(f"EXIDEL_CMAKE_BUILD_DIR={tree}: not a configured CMake tree")
        else:
            build = Path(self.build_temp).resolve() / "cmake"
            configure = ["cmake", "-S", str(ROOT), "-B", str(build),
                         "-DCMAKE_BUILD_TYPE=Release", "-DEXIDEL_BUILD_TESTS=OFF",
                         "-DEXIDEL_BUILD_BENCH=OFF", "-DEXIDEL_BUILD_CLI=ON",
                         "-DEXIDEL_BUILD_PYTHON=ON", "-DEXIDEL_INSTALL=OFF",
                         f"-DPython_EXECUTABLE={sys.executable}"]
            if shutil.which("ninja") and not (build / "CMakeCache.txt").exists():
                configure += ["-G", "Ninja"]
            try:
                import pybind11
                configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
            except ImportError:
                pass  # CMake finds pybind11's system package by itself
            run(configure + shlex.split(os.environ.get("CMAKE_ARGS", "")))
        run(["cmake", "--build", str(build), "--target", *TARGETS])

        module = build / "python" / "exidel" / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        command = build / "cli" / "exidel"
        for path in (module, command):
            if not path.is_file():
                raise RuntimeError(f"setup.py: the build did not produce {path}")
        target = Path(self.get_ext_fullpath(ext.name))
        package = target.parent
        (package / "bin").mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, target)
        shutil.copy2(command, package / "bin" / "exidel")
        (package / "_paths.py").write_text(
            "# Written by setup.py (pip): this package's own copy of the `exidel` command.\n"
            "import os\n\n"
            "cli = os.path.join(os.path.dirname(os.path.abspath(__file__)), \"bin\", \"exidel\")\n",
            encoding="utf-8")
        # The command on the environment's PATH too (pip installs data files under its
        # prefix: <venv>/bin/exidel).
        self.distribution.data_files = [("bin", [str(package / "bin" / "exidel")])]


# setuptools' own directory (and its metadata), out of the way of the CMake tree build/.
base = os.path.abspath(os.environ.get("EXIDEL_SETUP_BUILD_BASE") or ROOT / "build" / "pip")
os.makedirs(base, exist_ok=True)
options = {"build": {"build_base": base}, "egg_info": {"egg_base": base}}

setup(
    version=project_version(),
    packages=["exidel"],
    package_dir={"exidel": "python/exidel"},
    ext_modules=[Extension("exidel._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options=options,
)
