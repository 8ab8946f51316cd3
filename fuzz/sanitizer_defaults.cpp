// geomcheck — the AddressSanitizer defaults of every fuzz target.
//
// ASan keeps each freed block in a quarantine before reusing its memory, so
// that a later access to it is reported as a use after free; by default
// the quarantine holds 256 MB. The fuzz targets free hundreds of small
// blocks per input (CGAL's exact numbers in the Delaunay checker, the
// engine's rationals), so with 256 MB every allocation lands on memory not
// touched for seconds: page faults, cold caches, and a third of
// fuzz_delaunay_2d's time. OSS-Fuzz's runner fuzzes with a 10 MB
// quarantine (quarantine_size_mb=10 in its base-runner image); so do these
// targets. A use after free is still caught while the block is among the
// last 10 MB freed, which spans many inputs of every target here.
//
// ASan reads these first and the ASAN_OPTIONS environment variable after
// them, so `ASAN_OPTIONS=quarantine_size_mb=256 ./fuzz_x ...` restores the
// default for a run (OSS-Fuzz and ClusterFuzzLite set their own).
extern "C" const char* __asan_default_options() { return "quarantine_size_mb=10"; }
