// geomcheck — GMP's memory in the fuzz targets: blocks kept for reuse by size.
//
// The truth's certificates and several checks compute in GMP rationals,
// which allocate and free a block of limbs per operation. Under ASan every
// malloc and free records a stack trace and every free goes through the
// quarantine: in the engine-backed targets that bookkeeping was a fifth of
// a run. It buys nothing for these blocks: their limbs are only ever read
// and written inside libgmp, which is not instrumented, so ASan never
// checks an access to them; our code holds the mpz/mpq structs (which stay
// ordinary, checked memory) and boost's wrappers free them.
//
// So, in the fuzz targets only, GMP gets allocation functions that keep each
// freed block on a free list by its exact size and hand it out again for a
// request of that size. GMP passes the block's size to free and realloc;
// a block is only ever reused for a request no larger than the size it was
// freed with, which never exceeds what it holds (a block allocated before
// these functions were installed is malloc's, of at least that size). The
// lists stay reachable, so LeakSanitizer reports none of them.
#include <gmp.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <atomic>

namespace {

constexpr std::size_t kLargest = std::size_t{1} << 14;  // larger blocks go back to malloc
struct Node {
  Node* next;
};
Node* free_list[kLargest + 1];
// A spin lock: the targets run their checks on one thread, so it is never
// contended, and an atomic exchange costs far less than a mutex behind the
// sanitizers' interceptors (pthread_mutex_lock and unlock were 7% of an
// engine-backed target's run).
std::atomic_flag busy = ATOMIC_FLAG_INIT;
struct Hold {
  Hold() {
    while (busy.test_and_set(std::memory_order_acquire)) {
    }
  }
  ~Hold() { busy.clear(std::memory_order_release); }
};

bool pooled(std::size_t n) { return n >= sizeof(Node) && n <= kLargest; }

void* allocate(std::size_t n) {
  if (pooled(n)) {
    const Hold hold;
    if (Node* b = free_list[n]) {
      free_list[n] = b->next;
      return b;
    }
  }
  void* p = std::malloc(n < sizeof(Node) ? sizeof(Node) : n);
  if (p == nullptr) std::abort();
  return p;
}

void release(void* p, std::size_t n) {
  if (p == nullptr) return;
  if (!pooled(n)) {
    std::free(p);
    return;
  }
  const Hold hold;
  Node* b = static_cast<Node*>(p);
  b->next = free_list[n];
  free_list[n] = b;
}

void* reallocate(void* p, std::size_t old_size, std::size_t new_size) {
  void* q = allocate(new_size);
  if (p != nullptr) std::memcpy(q, p, old_size < new_size ? old_size : new_size);
  release(p, old_size);
  return q;
}

struct Install {
  Install() { mp_set_memory_functions(allocate, reallocate, release); }
} install;

}  // namespace
