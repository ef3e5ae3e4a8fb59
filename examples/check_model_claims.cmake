# The model keeps the attracting centre fixed (docs/model.md §1): an example that speaks of an orbit must
# also say that the centre is fixed, so that no scenario passes itself off as orbital motion. An
# orbit scenario (an [orbit] section, docs/orbit.md) has the orbital model and is exempt, and so is
# a sweep file over one (its `scenario = "..."` has an [orbit] section).
#   cmake -DEXAMPLES=DIR -P check_model_claims.cmake
file(GLOB files ${EXAMPLES}/*.toml)
set(failed "")
foreach(f ${files})
  file(READ ${f} text)
  string(TOLOWER "${text}" text)
  if(text MATCHES "\nscenario = \"([^\"]+)\"")
    file(READ ${EXAMPLES}/${CMAKE_MATCH_1} base)
    string(TOLOWER "${base}" base)
    if(base MATCHES "\n\\[orbit\\]")
      continue()
    endif()
  endif()
  if(text MATCHES "orbit" AND NOT text MATCHES "centre fixed" AND NOT text MATCHES "\n\\[orbit\\]")
    list(APPEND failed ${f})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "speak of an orbit without saying the centre is fixed: ${failed}")
endif()
