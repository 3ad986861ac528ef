tl_module(movie SOURCES tl_movie.c DEPS core image)
