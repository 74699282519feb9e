// gestura-bench: Google Benchmark workloads W1… (see docs/benchmarks.md). Each workload lives in its
// own file; this one only provides main().
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
