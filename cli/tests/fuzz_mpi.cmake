# ctest -L mpi: `exidel fuzz predicates` and `exidel fuzz triangulations` under
# `mpiexec -np 2` give the summary and the report of a single process (timings aside), and
# two ranks resume a single process's checkpoint.
#   cmake -DEXIDEL=<exidel> -DMPIEXEC=<mpiexec> -DWORK=<dir> -P fuzz_mpi.cmake
# Says "SKIPPED:" (the test's SKIP_REGULAR_EXPRESSION) when exidel was built without MPI.
if(NOT MPIEXEC)
  message("SKIPPED: MPI was not found when exidel was configured (Debian: libopenmpi-dev openmpi-bin)")
  return()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(options fuzz predicates -k long-double -n 30000 --seed 11 --reports 5 --no-progress)
# Two ranks on any machine (--oversubscribe), as root too (the test machines run as root;
# Open MPI refuses it unless told).
set(mpi ${MPIEXEC} -np 2 --oversubscribe --allow-run-as-root)

# run(<name> <expected exit status> <command...>)
function(run name expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL expected)
    message(FATAL_ERROR "${name}: exit status ${status}\n${out}\n${err}")
  endif()
  string(REGEX REPLACE "[^\n]*\n$" "" out "${out}")  # the timing line
  set(${name}_out "${out}" PARENT_SCOPE)
  file(READ ${WORK}/${name}.json json)
  string(JSON ranks GET "${json}" run ranks)
  set(${name}_ranks ${ranks} PARENT_SCOPE)
  string(JSON json REMOVE "${json}" seconds)
  string(JSON json REMOVE "${json}" run)
  set(${name}_json "${json}" PARENT_SCOPE)
endfunction()

function(expect_same a b)
  if(NOT "${${a}_json}" STREQUAL "${${b}_json}")
    message(FATAL_ERROR "summaries differ:\n${a}: ${${a}_json}\n${b}: ${${b}_json}")
  endif()
  if(NOT "${${a}_out}" STREQUAL "${${b}_out}")
    message(FATAL_ERROR "reports differ:\n${a}:\n${${a}_out}\n${b}:\n${${b}_out}")
  endif()
endfunction()

# Exit status 1: long double disagrees with exact.
run(solo 1 ${EXIDEL} ${options} -j 2 --summary ${WORK}/solo.json --checkpoint ${WORK}/solo.ckpt --keep-checkpoint)
run(mpi 1 ${mpi} ${EXIDEL} ${options} --summary ${WORK}/mpi.json --checkpoint ${WORK}/mpi.ckpt)
if(NOT mpi_ranks EQUAL 2)
  message(FATAL_ERROR "the MPI run says it ran on ${mpi_ranks} ranks")
endif()
expect_same(solo mpi)

# Two ranks resume what one process left: half of its stripes removed.
file(GLOB stripes ${WORK}/solo.ckpt/stripe-*)
list(LENGTH stripes count)
# 30000 queries: 118 blocks of 256, 8 blocks a stripe (fuzz.cpp's Layout), 15 stripes.
if(NOT count EQUAL 15)
  message(FATAL_ERROR "expected 15 stripe files, found ${count}")
endif()
list(SORT stripes)
foreach(i RANGE 0 14 2)
  list(GET stripes ${i} stripe)
  file(REMOVE ${stripe})
endforeach()
run(resumed 1 ${mpi} ${EXIDEL} ${options} --summary ${WORK}/resumed.json --checkpoint ${WORK}/solo.ckpt --resume)
expect_same(solo resumed)
if(EXISTS ${WORK}/solo.ckpt)
  message(FATAL_ERROR "the finished campaign's checkpoint was not removed")
endif()

# Triangulations: every method with the adaptive kernel, certified (exit status 0).
set(options fuzz triangulations --sets 40 --sizes 3-30 --seed 11 --no-progress)
run(tsolo 0 ${EXIDEL} ${options} -j 2 --summary ${WORK}/tsolo.json --checkpoint ${WORK}/tsolo.ckpt)
run(tmpi 0 ${mpi} ${EXIDEL} ${options} --summary ${WORK}/tmpi.json --checkpoint ${WORK}/tmpi.ckpt)
if(NOT tmpi_ranks EQUAL 2)
  message(FATAL_ERROR "the MPI run says it ran on ${tmpi_ranks} ranks")
endif()
expect_same(tsolo tmpi)
message("exidel fuzz: 2 MPI ranks gave the single process's summaries and reports, and resumed its checkpoint")
