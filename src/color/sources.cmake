# The colour spaces of the frames (names, chromaticities, the display
# table's layout), without OpenColorIO.
tl_module(color SOURCES tl_color.c)
