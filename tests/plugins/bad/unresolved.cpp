// A broken shared object: it needs a function no library defines, so dlopen with RTLD_NOW fails.
extern "C" int sxk_test_undefined_function();

extern "C" __attribute__((visibility("default"))) int sxk_test_calls_missing() {
    return sxk_test_undefined_function();
}
