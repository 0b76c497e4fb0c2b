// Linked into the test binaries of the QMF_SANITIZE build only: the sanitizers' default options,
// read by their runtimes before main (and by test discovery, which runs the binaries too), so no
// environment variable is needed. The leak suppressions are a committed file, each entry commented.
extern "C" {
const char *__asan_default_options() { return "detect_leaks=1:strict_string_checks=1:check_initialization_order=1"; }
const char *__ubsan_default_options() { return "print_stacktrace=1"; }
const char *__lsan_default_options() { return "suppressions=" QMF_LSAN_SUPPRESSIONS ":print_suppressions=0"; }
}
