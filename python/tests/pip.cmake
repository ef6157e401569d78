# Run by ctest (python.pip): `pip install --no-build-isolation .` of the source tree into a
# fresh virtual environment (--system-site-packages: numpy from the system), offline, then the
# installed package imported from outside the source and build trees with nothing on
# PYTHONPATH (its version, a certified triangulation, the `exidel` command that
# exidel._paths.cli names, and the copy on the environment's PATH), then `pip wheel` and
# the wheel's contents. setup.py packages this build tree (EXIDEL_CMAKE_BUILD_DIR: only
# exidel_python and exidel_cli, already built) so the test costs seconds, not a second
# build of the library; setuptools works in WORK_DIR, so the source tree stays as it was.
#
#   cmake -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK_DIR=... -DPYTHON=... -DVERSION=... -P pip.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var SOURCE_DIR BUILD_DIR WORK_DIR PYTHON VERSION)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "pip.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

execute_process(COMMAND ${PYTHON} -c "import venv, ensurepip, setuptools, wheel"
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
if(NOT status EQUAL 0)
  message("SKIPPED: ${PYTHON} lacks venv, ensurepip, setuptools or wheel "
          "(Debian: python3-venv, python3-setuptools, python3-wheel)")
  return()
endif()

function(step what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status})")
  endif()
endfunction()

set(venv ${WORK_DIR}/venv)
step("python3 -m venv" ${PYTHON} -m venv --system-site-packages ${venv})
set(env ${CMAKE_COMMAND} -E env --unset=PYTHONPATH --unset=EXIDEL_CLI
    EXIDEL_CMAKE_BUILD_DIR=${BUILD_DIR} EXIDEL_SETUP_BUILD_BASE=${WORK_DIR}/setuptools
    PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1)
step("pip install" ${env} ${venv}/bin/pip install --no-build-isolation --no-index ${SOURCE_DIR})

set(check [=[
import os, sys, subprocess
import numpy as np
import exidel, exidel._paths
venv, version = sys.argv[1:]
package = os.path.dirname(os.path.realpath(exidel.__file__))
assert package.startswith(os.path.realpath(venv)), package
assert exidel.__version__ == version, exidel.__version__
pts = np.random.default_rng(1).random((1000, 2))
assert exidel.Delaunay(pts).certify().ok
assert os.path.realpath(exidel._paths.cli) == os.path.join(package, "bin", "exidel"), exidel._paths.cli
for cli in (exidel._paths.cli, os.path.join(venv, "bin", "exidel")):
    out = subprocess.run([cli, "--version"], capture_output=True, text=True, check=True).stdout
    assert out.startswith("exidel " + version), out
print("exidel", exidel.__version__, "from", package, "and", exidel._paths.cli)
]=])
step("the installed package's check" ${env} ${venv}/bin/python -c "${check}" ${venv} ${VERSION})

step("pip wheel" ${env} ${venv}/bin/pip wheel --no-build-isolation --no-deps --no-index
     -w ${WORK_DIR}/wheels ${SOURCE_DIR})
set(check_wheel [=[
import glob, sys, zipfile
wheels, version = sys.argv[1:]
found = glob.glob(wheels + "/*.whl")
assert len(found) == 1, found
name = found[0].rsplit("/", 1)[1]
assert name.startswith(f"exidel-{version}-cp{sys.version_info[0]}{sys.version_info[1]}-"), name
with zipfile.ZipFile(found[0]) as z:
    files = {i.filename: i for i in z.infolist()}
    for f in ("exidel/__init__.py", "exidel/_delaunay.py", "exidel/_paths.py",
              "exidel/bin/exidel", f"exidel-{version}.data/data/bin/exidel"):
        assert f in files, (f, sorted(files))
    assert [f for f in files if f.startswith("exidel/_core.")], sorted(files)
    for f in ("exidel/bin/exidel", f"exidel-{version}.data/data/bin/exidel"):
        assert files[f].external_attr >> 16 & 0o111, f"{f} is not executable"
print("wheel", name, len(files), "files")
]=])
step("the wheel's check" ${PYTHON} -c "${check_wheel}" ${WORK_DIR}/wheels ${VERSION})
