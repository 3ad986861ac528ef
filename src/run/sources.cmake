#A render run : a timeline's frames through the pipeline into files and a
#movie, resumable and interruptible(what `tideline render` runs).
tl_module(run SOURCES tl_run.c DEPS color core image job movie passes render scene timeline)
