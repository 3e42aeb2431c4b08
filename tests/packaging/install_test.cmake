# Installs the build into a scratch prefix (cmake --install) and runs the
# installed program from a directory outside the source tree: a scene, a plan
# and a validation, all on the data under <prefix>/share/coilsim. A coil that
# only the installed catalogue holds proves the program reads that one, not
# the source tree it was built from.
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DSCRATCH=... -P install_test.cmake
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH}/work)
set(prefix ${SCRATCH}/prefix)

function(check_run what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${SCRATCH}/work
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what}: exit ${code}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

check_run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
set(coilsim ${prefix}/bin/coilsim)
set(data ${prefix}/share/coilsim)
foreach(f ${coilsim} ${data}/assets/coils/finishing-2x10.json ${data}/scenes/default.json
        ${data}/assets/meshes/sidewall-7mm.stl ${data}/timelines/push-default.json
        ${data}/examples/measurements/soft-catheter-helix.json
        ${prefix}/share/bash-completion/completions/coilsim ${prefix}/share/applications/coilsim.desktop)
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
file(READ ${prefix}/share/applications/coilsim.desktop desktop)
if(NOT desktop MATCHES "Exec=${coilsim} run ${data}/scenes/default.json")
  message(FATAL_ERROR "the desktop entry does not open the installed default scene:\n${desktop}")
endif()

# A coil only the installed catalogue has.
file(READ ${data}/assets/coils/finishing-2x10.json coil)
string(REPLACE "\"finishing-2x10\"" "\"installed-probe-2x10\"" coil "${coil}")
file(WRITE ${data}/assets/coils/installed-probe-2x10.json "${coil}")
set(ENV{COILSIM_DATA_DIR} "")
check_run("completion coils" ${coilsim} completion coils)
if(NOT out MATCHES "installed-probe-2x10")
  message(FATAL_ERROR "the installed coilsim does not read its installed catalogue:\n${out}")
endif()

check_run("run" ${coilsim} run ${data}/scenes/cantilever-static.json --headless --out ${SCRATCH}/work/r.json)
if(NOT out MATCHES "static, converged")
  message(FATAL_ERROR "run: ${out}")
endif()
check_run("plan" ${coilsim} plan ${data}/scenes/cases/sphere-7mm-wide-neck.json --coils installed-probe-2x10
          --no-screenshots --out ${SCRATCH}/work/plan)
if(NOT EXISTS ${SCRATCH}/work/plan/plan.json OR NOT out MATCHES "installed-probe-2x10")
  message(FATAL_ERROR "plan: ${out}")
endif()
check_run("validate" ${coilsim} validate ${data}/examples/measurements/soft-catheter-helix.json --no-plots
          --out ${SCRATCH}/work/v)
if(NOT EXISTS ${SCRATCH}/work/v/report.json)
  message(FATAL_ERROR "validate wrote no report: ${out}")
endif()

# COILSIM_DATA_DIR overrides, and a wrong one is named in the error.
set(ENV{COILSIM_DATA_DIR} ${SCRATCH}/nowhere)
execute_process(COMMAND ${coilsim} completion coils RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET)
if(code EQUAL 0 OR NOT err MATCHES "nowhere")
  message(FATAL_ERROR "COILSIM_DATA_DIR=${SCRATCH}/nowhere: exit ${code}, ${err}")
endif()
message(STATUS "installed coilsim ran a scene, a plan and a validation from ${prefix}")
