// A shared module that is not an mhbench plug-in (no mhbench_plugin entry point): mhbench must say
// so rather than fail obscurely.
extern "C" __attribute__((visibility("default"))) int some_other_library_function() {
    return 42;
}
