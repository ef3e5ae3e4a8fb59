# The repository stands alone: a clone of it, in a folder with nothing beside it, runs an example
# that reads the repository's own data (the Eros polyhedron of data/polyhedra), and no tracked file
# refers to a folder outside the repository.
#   cmake -DNEWTOP=path/to/newtop -DSRC=source/dir -DDIR=scratch/dir -P clone_check.cmake
# Prints "SKIP: ..." and succeeds when SRC is not a git working tree (a source archive) or git is
# missing; the test's SKIP_REGULAR_EXPRESSION turns that into a skipped test.
find_program(GIT git)
if(NOT GIT)
  message("SKIP: git not found")
  return()
endif()
execute_process(COMMAND ${GIT} -C ${SRC} rev-parse --is-inside-work-tree
                OUTPUT_VARIABLE inside ERROR_QUIET RESULT_VARIABLE code)
if(NOT code EQUAL 0 OR NOT inside MATCHES "true")
  message("SKIP: ${SRC} is not a git working tree")
  return()
endif()

# A clone has the committed files only: the data must be committed, not merely present in SRC.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
execute_process(COMMAND ${GIT} clone --quiet ${SRC} ${DIR}/clone RESULT_VARIABLE code
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "git clone --quiet ${SRC} ${DIR}/clone: exit code ${code}\n${err}")
endif()

# The Eros example, run from the scratch folder so that no path can resolve against SRC.
set(example ${DIR}/clone/examples/exact_eros_spacecraft.toml)
execute_process(COMMAND ${NEWTOP} simulate ${example} --json WORKING_DIRECTORY ${DIR}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "newtop simulate ${example} --json (in a clone): exit code ${code}\n${err}")
endif()
string(JSON outcome ERROR_VARIABLE json_error GET "${out}" outcome)
if(json_error OR NOT outcome STREQUAL "finished")
  message(FATAL_ERROR "newtop simulate ${example}: outcome '${outcome}' ${json_error}\n${out}")
endif()
string(JSON kind ERROR_VARIABLE json_error GET "${out}" field mass_model)
if(json_error OR NOT kind STREQUAL "polyhedron")
  message(FATAL_ERROR "newtop simulate ${example}: expected the field of the Eros polyhedron, "
                      "found mass model '${kind}' ${json_error}")
endif()

# Nothing tracked refers to the folder beside the repository.
execute_process(COMMAND ${GIT} -C ${DIR}/clone grep -n -e "\\.\\./shared"
                RESULT_VARIABLE code OUTPUT_VARIABLE hits)
if(code EQUAL 0)
  message(FATAL_ERROR "tracked files name the shared folder beside the repository:\n${hits}")
endif()
file(REMOVE_RECURSE ${DIR})
message("clone of ${SRC} ran ${example}: outcome finished")
