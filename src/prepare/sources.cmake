set(TL_PREPARE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/tl_prepare.c
                       ${CMAKE_CURRENT_LIST_DIR}/tl_prepare_rect.c)
