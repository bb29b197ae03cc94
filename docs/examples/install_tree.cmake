# ctest install_tree: install the build into a fresh prefix, check what landed there, build
# docs/examples/outside_project against it with find_package(simplexkit), and run the outside
# programs (the stats plug-in on a mesh of its own; a snap cut of a deforming body with undo) and
# the installed sxk (which must use the installed library and plug-ins, never the build tree's).
#
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DBUILD_TYPE=...] -P install_tree.cmake
foreach(variable BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${variable})
    message(FATAL_ERROR "install_tree: -D${variable}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "install_tree: '${command}' failed (${result}):\n${output}\n${error}")
  endif()
  set(output "${output}" PARENT_SCOPE)
  set(error "${error}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

include(GNUInstallDirs)
foreach(file
    ${CMAKE_INSTALL_BINDIR}/sxk
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/mesh.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugin.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugin_host.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/simulation.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugins/snapcut.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugins/delaunaycut.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugins/needle.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugins/degeneracy.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugins/elasticity.hpp
    ${CMAKE_INSTALL_INCLUDEDIR}/sxk/plugins/render.hpp
    ${CMAKE_INSTALL_LIBDIR}/libsimplexkit.so
    ${CMAKE_INSTALL_LIBDIR}/simplexkit/plugins/stats.so
    ${CMAKE_INSTALL_LIBDIR}/cmake/simplexkit/simplexkitConfig.cmake
    ${CMAKE_INSTALL_LIBDIR}/cmake/simplexkit/simplexkitConfigVersion.cmake
    ${CMAKE_INSTALL_LIBDIR}/cmake/simplexkit/simplexkitTargets.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install_tree: ${file} was not installed")
  endif()
endforeach()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/docs/examples/outside_project -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${CMAKE_COMMAND} -E env --unset=SXK_PLUGIN_PATH --unset=LD_LIBRARY_PATH ${WORK_DIR}/build/outside_app)
message(STATUS "outside_app:\n${output}")
if(NOT output MATCHES "stats [0-9.]+ from ${prefix}/${CMAKE_INSTALL_LIBDIR}/simplexkit/plugins/stats.so")
  message(FATAL_ERROR "install_tree: outside_app did not use the installed stats plug-in:\n${output}")
endif()

# the snap cutter cutting the elasticity plug-in's simulation, through typed options, undone and
# redone byte for byte (needs the snapcut, degeneracy and elasticity plug-ins, built by default)
if(EXISTS ${prefix}/${CMAKE_INSTALL_LIBDIR}/simplexkit/plugins/snapcut.so AND
   EXISTS ${prefix}/${CMAKE_INSTALL_LIBDIR}/simplexkit/plugins/elasticity.so)
  run(${CMAKE_COMMAND} -E env --unset=SXK_PLUGIN_PATH --unset=LD_LIBRARY_PATH ${WORK_DIR}/build/outside_cut)
  message(STATUS "outside_cut:\n${output}")
  if(NOT output MATCHES "cut: [0-9]+ steps, [1-9][0-9]* cut faces, undone byte for byte, redone byte for byte")
    message(FATAL_ERROR "install_tree: outside_cut did not cut and undo:\n${output}\n${error}")
  endif()
endif()

# the installed sxk: RPATH $ORIGIN/../lib, plug-ins from the install folder only
run(${CMAKE_COMMAND} -E env --unset=SXK_PLUGIN_PATH --unset=LD_LIBRARY_PATH ${prefix}/${CMAKE_INSTALL_BINDIR}/sxk plugins)
message(STATUS "installed sxk plugins:\n${output}${error}")
if(NOT output MATCHES "file: ${prefix}/${CMAKE_INSTALL_LIBDIR}/simplexkit/plugins/stats.so")
  message(FATAL_ERROR "install_tree: the installed sxk did not load the installed plug-in:\n${output}")
endif()
if(NOT error STREQUAL "")
  message(FATAL_ERROR "install_tree: the installed sxk complained:\n${error}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
