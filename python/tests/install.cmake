# Run by ctest (python.install): `cmake --install` of this build into a fresh prefix, then
# the installed package imported by the interpreter it was built for, from the directory
# the install chose (EXIDEL_PYTHON_INSTALL_DIR), with nothing of the build tree on
# PYTHONPATH: its version, a certified triangulation, and the `exidel` command it finds.
#
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DPYTHON=... -DPYTHON_DIR=... -P install.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var BUILD_DIR WORK_DIR PYTHON PYTHON_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
set(check [=[
import os, sys, subprocess
import numpy as np
import exidel, exidel._paths
assert os.path.realpath(exidel.__file__).startswith(os.path.realpath(sys.argv[1])), exidel.__file__
pts = np.random.default_rng(1).random((1000, 2))
assert exidel.Delaunay(pts).certify().ok
assert os.path.realpath(exidel._paths.cli) == os.path.realpath(os.path.join(sys.argv[1], "bin", "exidel")), exidel._paths.cli
print(subprocess.run([exidel._paths.cli, "--version"], capture_output=True, text=True, check=True).stdout.strip())
print("exidel", exidel.__version__, "from", os.path.dirname(exidel.__file__))
]=])
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONPATH
                        PYTHONPATH=${prefix}/${PYTHON_DIR}
                        ${PYTHON} -c "${check}" ${prefix}
                WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed module failed its check (${status})")
endif()
