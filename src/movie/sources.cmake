tl_module(movie SOURCES tl_movie.c tl_movie_frames.c DEPS core image job)
