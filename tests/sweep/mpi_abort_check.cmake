# newtop sweep under mpirun, aborted by killing a worker rank (SIGKILL): the sweep leaves its
# checkpoint and no temporary (OUT.partial-PID) beside it, and --resume completes it, leaving
# neither.
#   cmake -DNEWTOP=... -DMPIEXEC=... -DSCENARIO=... -DDIR=... -P mpi_abort_check.cmake
set(mpi ${MPIEXEC} --oversubscribe --allow-run-as-root -np 3)
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
execute_process(COMMAND ${mpi} ${CMAKE_COMMAND} -E true RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message("SKIP: mpirun cannot start processes here (exit ${rc}): ${err}")
  return()
endif()
# A MEGNO map long enough (seconds on any machine) to be killed while it runs.
file(WRITE ${DIR}/slow.toml "scenario = \"${SCENARIO}\"\nquantities = [\"megno\"]\n"
     "[[axes]]\nkey = \"initial.omega[0]\"\nstart = -1.5\nstop = 1.5\ncount = 10\n"
     "[[axes]]\nkey = \"initial.omega[1]\"\nstart = -1.5\nstop = 1.5\ncount = 10\n"
     "[integrate]\nt_end = 3000.0\nstep = 0.02\n")
# mpirun in the background; once the first points are in the checkpoint (the sweep is running),
# SIGKILL to its last child (a worker rank).
string(REPLACE ";" " " mpi_line "${mpi}")
file(WRITE ${DIR}/abort.sh
     "${mpi_line} ${NEWTOP} sweep ${DIR}/slow.toml --quiet --out ${DIR}/out.csv &\n"
     "mp=$!\nfor i in $(seq 600); do [ -s ${DIR}/out.csv.checkpoint ] && break; sleep 0.1; done\n"
     "w=$(pgrep -P $mp | tail -n 1)\n"
     "if [ -z \"$w\" ]; then echo 'no worker to kill'; wait $mp; exit 10; fi\n"
     "kill -9 $w\nwait $mp\nexit 0\n")
execute_process(COMMAND sh ${DIR}/abort.sh RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "abort: the sweep ended before a worker could be killed: ${out} ${err}")
endif()
if(EXISTS ${DIR}/out.csv)
  message(FATAL_ERROR "abort: the sweep was killed, yet ${DIR}/out.csv was written")
endif()
file(GLOB partials ${DIR}/out.csv.partial-*)
if(partials)
  message(FATAL_ERROR "abort: temporaries left beside the checkpoint: ${partials}")
endif()
execute_process(COMMAND ${mpi} ${NEWTOP} sweep ${DIR}/slow.toml --quiet --resume
                        --out ${DIR}/out.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(GLOB left ${DIR}/out.csv.*)
if(NOT rc EQUAL 0 OR NOT EXISTS ${DIR}/out.csv OR left)
  message(FATAL_ERROR "resume: exit ${rc}, left ${left}: ${out} ${err}")
endif()
