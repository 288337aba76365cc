// The library tls_probe.cpp loads: a thread-local variable of a library loaded with
// dlopen, whose block glibc allocates with malloc when a thread first touches it.
extern "C" char* tls_probe_touch();

namespace {
thread_local char block[40];
} // namespace

extern "C" char* tls_probe_touch()
{
    block[0] = 1;
    return block;
}
