set(TL_CLI_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/tl_args.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_cli_common.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_cli_still.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_cli_timeline.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_cli_render.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_cli_preview.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_cli_compare.c)
