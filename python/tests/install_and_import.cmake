# Installs the python component of BUILD_DIR into PREFIX and imports holefill from there (not
# from the build tree): `cmake --install` must give a working package.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                        --component python
                RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "cmake --install failed")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${PREFIX}/${PACKAGE_DIR} ${PYTHON} -c
          "import holefill, sys; p = holefill.__file__; assert p.startswith(sys.argv[1]), p; m = holefill.load(sys.argv[2]); print(len(holefill.holes(m)))"
          ${PREFIX} ${MESH}
  RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(failed OR NOT out STREQUAL "3\n")
  message(FATAL_ERROR "the installed module did not load the bunny's 3 holes: ${out}${err}")
endif()
