# newtop sweep under mpirun (docs/sweep.md): the same bytes from 3 ranks as from 2 threads, in CSV
# and HDF5, and bad input as one line (from rank 0 only) with exit 2.
#   cmake -DNEWTOP=... -DMPIEXEC=... -DSWEEP=... -DDIR=... -P mpi_check.cmake
set(mpi ${MPIEXEC} --oversubscribe --allow-run-as-root -np 3)
file(MAKE_DIRECTORY ${DIR})
# A machine where mpirun cannot start three processes at all (no MPI runtime usable in a
# container, say) skips this test rather than passing it.
execute_process(COMMAND ${mpi} ${CMAKE_COMMAND} -E true RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message("SKIP: mpirun cannot start processes here (exit ${rc}): ${err}")
  return()
endif()
foreach(ext csv h5)
  file(REMOVE ${DIR}/threads.${ext} ${DIR}/ranks.${ext})
  execute_process(COMMAND ${NEWTOP} sweep ${SWEEP} --quiet --threads 2 --out ${DIR}/threads.${ext}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "threads: exit ${rc}")
  endif()
  execute_process(COMMAND ${mpi} ${NEWTOP} sweep ${SWEEP} --quiet --out ${DIR}/ranks.${ext}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "mpirun: exit ${rc}: ${out} ${err}")
  endif()
  string(REGEX MATCHALL "worker ranks" ranks "${out}")
  if(NOT ranks)
    message(FATAL_ERROR "mpirun: expected the points shared among worker ranks, found: ${out}")
  endif()
  file(SHA256 ${DIR}/threads.${ext} a)
  file(SHA256 ${DIR}/ranks.${ext} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${ext}: 3 ranks and 2 threads wrote different files")
  endif()
endforeach()

file(WRITE ${DIR}/bad.toml "scenario = \"${SWEEP}\"\nquantities = [\"drift\"]\n")
execute_process(COMMAND ${mpi} ${NEWTOP} sweep ${DIR}/bad.toml --out ${DIR}/bad.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "newtop: error:[^\n]*" lines "${out}${err}")
list(LENGTH lines count)
if(rc EQUAL 0 OR NOT count EQUAL 1 OR EXISTS ${DIR}/bad.csv)
  message(FATAL_ERROR "bad input under mpirun: exit ${rc}, ${count} error lines: ${out} ${err}")
endif()
