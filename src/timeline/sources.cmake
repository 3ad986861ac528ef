set(TL_TIMELINE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/tl_ease.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_curve.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_curve_prepare.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_path.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_channels.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_timeline.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_parse.c)
