#pragma once
// Runs independent work items on every core: body(i) for each i in [0, count), items handed out one
// at a time from a shared counter (items may differ a lot in cost, e.g. signs in a lexicon), on
// worker_count() threads, the calling thread among them. Results go wherever body writes them by
// index, so the caller keeps its own order. The first exception thrown by a body is rethrown here
// after the other threads have stopped taking items.
#include <cstddef>
#include <functional>

namespace gestura {

// The threads parallel_for uses when asked for 0: the machine's hardware threads (at least 1), or
// GESTURA_THREADS when set to a positive number.
unsigned worker_count();

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& body, unsigned threads = 0);

}  // namespace gestura
