# The bench's engine: rounds of timed renders, errors against `reference`,
# the reference cache and the reports (the command only parses and prints).
tl_module(bench SOURCES tl_bench.c tl_bench_presets.c tl_bench_report.c tl_bench_cache.c
  DEPS core cutscene image job metrics render scene shader timeline)
