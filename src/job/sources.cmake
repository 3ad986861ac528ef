tl_module(job SOURCES tl_job.c DEPS core)
