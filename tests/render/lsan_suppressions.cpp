// OSMesa keeps a process-wide list of the buffers passed to
// OSMesaMakeCurrent and never frees it; that is Mesa's, not ours, so the
// asan preset should not fail on it. Only read when LeakSanitizer is linked.
extern "C" const char* __lsan_default_suppressions();  // NOLINT(bugprone-reserved-identifier)
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
