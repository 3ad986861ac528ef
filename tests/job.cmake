# Job and movie tests.
tl_add_test(test_job SOURCES test_job.c LIBS tideline_core LABELS unit)
tl_add_test(test_movie SOURCES test_movie.c LIBS tideline_core LABELS unit)
tl_add_test(test_movie_sound SOURCES test_movie_sound.c LIBS tideline_core PkgConfig::SNDFILE
            LABELS unit)
