// A tally of the GL calls issued on this thread that set state, bind, upload and draw, for the
// figures a technique reports of its own calls (issue 41: the stencil technique's GL calls per
// light in --stats, docs/cli.md). Each call costs the driver's CPU time whatever it does, which
// is what a technique drawing a light at a time pays. The wrappers of this layer count the
// calls they make as they make them (binds, uniforms, program changes, buffer updates); code
// outside it that calls GL itself makes its calls through `counted` where a figure needs them
// (the pipeline state, the passes' barriers, the volume techniques' draws). Creating and
// deleting objects is not counted. Per thread, as a context is current on one thread.
#pragma once

#include <cstdint>

namespace manylights::gl {

namespace detail {
inline thread_local std::uint64_t callTally = 0;
}  // namespace detail

// The calls counted on this thread so far: a difference of two readings is what ran between.
inline std::uint64_t callTally() { return detail::callTally; }

// Calls `function` (a GL entry point) with `arguments`, counted.
template <typename Function, typename... Arguments>
void counted(Function function, Arguments... arguments)
{
    ++detail::callTally;
    function(arguments...);
}

}  // namespace manylights::gl
