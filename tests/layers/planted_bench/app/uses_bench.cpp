// A planted include of bench from the command line: the user's binary links
// no benchmark or peer, so check_layers.cmake must refuse this folder (ctest
// layers_refuse_bench_in_app).
#include "bench/bench.hpp"
