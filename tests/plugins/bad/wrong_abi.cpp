// A plug-in built against a future ABI: the host must read abi_version, refuse, and unload it
// without calling anything else.
#include <cstdint>

namespace {
struct FutureInfo {
    std::uint32_t abi_version;
    const char* something_new;
};
const FutureInfo info{999, "fields the host does not know"};
}  // namespace

extern "C" __attribute__((visibility("default"))) const void* sxk_plugin_entry() { return &info; }
