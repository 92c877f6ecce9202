// Fixed-partition parallel loops. Each task index writes only its own outputs, so results never
// depend on which thread ran a task or in which order.
#ifndef VHACD_SRC_THREAD_POOL_H_
#define VHACD_SRC_THREAD_POOL_H_

#include <cstddef>
#include <functional>

#include "context.h"

namespace vhacd {
namespace internal {

// Runs fn(i) for every i in [0, n) on up to ctx->num_threads() threads (the caller's thread
// included). Stops handing out tasks once ctx->Cancelled(); returns false in that case.
// `ctx` may be null (one thread, no cancellation). An exception thrown by fn stops the loop and
// is rethrown on the calling thread once every worker has joined.
bool ParallelFor(Context* ctx, size_t n, const std::function<void(size_t)>& fn);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_THREAD_POOL_H_
