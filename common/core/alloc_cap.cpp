// The global operator new, replaced (as C++ allows) to honour the cap of alloc_cap.h. With no
// cap in force, it is malloc as the default one is; the cap is thread-local, so
// library threads and the rest of the program are not affected.
#include "alloc_cap.h"
#include "memory.h"

#include <cstdlib>
#include <new>
#include <sys/stat.h>

namespace {
thread_local std::size_t cap = 0; // 0: none
}

extern "C" size_t fs_alloc_cap_begin(const char *path)
{
    struct stat st;
    double bound = stat(path, &st) == 0 ? 2064.0 * static_cast<double>(st.st_size) + 256e6 : 256e6;
    double avail = static_cast<double>(fs_memory_available());
    size_t saved = cap;
    cap = static_cast<std::size_t>(bound < avail ? bound : avail);
    return saved;
}

extern "C" void fs_alloc_cap_end(size_t previous) { cap = previous; }

void *operator new(std::size_t n)
{
    if (cap && n > cap) throw std::bad_alloc();
    void *p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    return p;
}
void *operator new[](std::size_t n) { return operator new(n); }
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }
// the nothrow forms too, so that every plain new and delete of the program pairs with
// these (the sanitizers check the pairing)
void *operator new(std::size_t n, const std::nothrow_t &) noexcept
{
    return cap && n > cap ? nullptr : std::malloc(n ? n : 1);
}
void *operator new[](std::size_t n, const std::nothrow_t &t) noexcept { return operator new(n, t); }
void operator delete(void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { std::free(p); }
