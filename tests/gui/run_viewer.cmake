# One GUI test: runs holefill-viewer in scripted mode under Xvfb (Mesa llvmpipe) and checks the
# screenshot with png_check. Variables: VIEWER, CHECKER, OUTPUT (png), ARGS (|-separated viewer
# arguments), CHECK (png_check's check), or EXPECT_EXIT (the viewer's expected non-zero status,
# with no screenshot check).
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message("SKIPPED: xvfb-run is not installed")
  return()
endif()
string(REPLACE "|" ";" ARGS "${ARGS}")
file(REMOVE ${OUTPUT})
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env LIBGL_ALWAYS_SOFTWARE=1
          ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${VIEWER} ${ARGS} --screenshot ${OUTPUT}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(DEFINED EXPECT_EXIT)
  if(NOT status EQUAL EXPECT_EXIT)
    message(FATAL_ERROR "holefill-viewer exited with ${status}, expected ${EXPECT_EXIT}")
  endif()
  if(NOT err MATCHES "holefill-viewer: ")
    message(FATAL_ERROR "holefill-viewer gave no message on stderr")
  endif()
  return()
endif()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "holefill-viewer exited with ${status}")
endif()
execute_process(COMMAND ${CHECKER} ${OUTPUT} ${CHECK} RESULT_VARIABLE checked)
if(NOT checked EQUAL 0)
  message(FATAL_ERROR "png_check ${CHECK} failed on ${OUTPUT}")
endif()
