// The global operator new, replaced (as C++ allows) to honour the cap of alloc_cap.h. With no
// cap in force, it allocates as the default one does (below); the cap is thread-local, so
// library threads and the rest of the program are not affected.
#include "alloc_cap.h"
#include "memory.h"

#include <cstdlib>
#include <dlfcn.h>
#include <new>
#include <sys/stat.h>

namespace
{
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

// Who allocates underneath. In a program, these operators are the global ones: they
// use malloc and free, as the default ones do. Inside libfluidsurf.so they stay local
// (api/exports.map exports fluidsurf_* only), while OpenVDB, VTK and OpenImageIO
// allocate with the process's global operator new (libstdc++'s, ASan's, or the host's
// own), and memory crosses between them (a std::vector grown in libopenvdb, freed in
// our inlined destructor): so each form forwards to its global namesake whenever that
// is not this very function, and every new pairs with its delete in either case.
namespace
{
template <typename F> F global_or_null(const char *name, F self)
{
    void *f = dlsym(RTLD_DEFAULT, name);
    return f && f != reinterpret_cast<void *>(self) ? reinterpret_cast<F>(f) : nullptr;
}
using new_fn = void *(*)(std::size_t);
using delete_fn = void (*)(void *);
void *plain_new(std::size_t n)
{
    void *p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    return p;
}
} // namespace

void *operator new(std::size_t n)
{
    static const new_fn next = global_or_null<new_fn>("_Znwm", &::operator new);
    if (cap && n > cap) throw std::bad_alloc();
    return next ? next(n) : plain_new(n);
}
void *operator new[](std::size_t n)
{
    static const new_fn next = global_or_null<new_fn>("_Znam", &::operator new[]);
    if (cap && n > cap) throw std::bad_alloc();
    return next ? next(n) : plain_new(n);
}
void operator delete(void *p) noexcept
{
    static const delete_fn next = global_or_null<delete_fn>("_ZdlPv", &::operator delete);
    next ? next(p) : std::free(p);
}
void operator delete[](void *p) noexcept
{
    static const delete_fn next = global_or_null<delete_fn>("_ZdaPv", &::operator delete[]);
    next ? next(p) : std::free(p);
}
void operator delete(void *p, std::size_t) noexcept { ::operator delete(p); }
void operator delete[](void *p, std::size_t) noexcept { ::operator delete[](p); }
// the nothrow forms too, so that every plain new and delete of the program pairs with
// these (the sanitizers check the pairing)
void *operator new(std::size_t n, const std::nothrow_t &) noexcept
{
    try {
        return ::operator new(n);
    } catch (const std::bad_alloc &) {
        return nullptr;
    }
}
void *operator new[](std::size_t n, const std::nothrow_t &) noexcept
{
    try {
        return ::operator new[](n);
    } catch (const std::bad_alloc &) {
        return nullptr;
    }
}
void operator delete(void *p, const std::nothrow_t &) noexcept { ::operator delete(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { ::operator delete[](p); }
