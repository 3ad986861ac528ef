# Which frames a run writes and where, resuming it, and the writer threads
# that encode frames while the next renders.
tl_module(job SOURCES tl_job.c tl_job_resume.c tl_writer.c DEPS core image scene
  EXTERNAL Threads::Threads)
