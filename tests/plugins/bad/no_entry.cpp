// A valid shared object that is not a simplexkit plug-in (no sxk_plugin_entry).
extern "C" __attribute__((visibility("default"))) int sxk_test_something_else() { return 42; }
