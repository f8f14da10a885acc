// Fuzz target: the session/preset JSON reader, through loadSessionFile (the
// file is read as `render --session` reads it: parse, sessionFromJson,
// validateSession). Found and failed on:
//  - a crash, hang or sanitizer report anywhere on the way;
//  - an exception other than InputError (bad input must be exit 2 with a
//    message, not a raw library exception and exit 1);
//  - an accepted session whose run cannot be planned without a crash
//    (segmentsOf, describePlan and the step total run before any step);
//  - an accepted session that, written back as `render` writes it, is refused
//    or reads back as a different session (every session the program writes
//    must be accepted by the program).

#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/output/frames.hpp"
#include "core/session/session.hpp"
#include "core/sim/segments.hpp"
#include "fuzz_support.hpp"

namespace {

using morphogen::InputError;
using morphogen::Session;
namespace fuzz = morphogen::fuzz;

std::string describe(const std::exception& e) {
    return std::string(typeid(e).name()) + ": " + e.what();
}

// What a run does with the session before its first step.
void plan(const Session& s) {
    try {
        (void)morphogen::segmentsOf(s);
        (void)morphogen::describePlan(s);
        (void)morphogen::sessionTotalSteps(s);
        (void)s.outputModel();
        (void)s.domain();
    } catch (const InputError&) {
        // A session the planner refuses is refused before any work: fine.
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::writeInput(data, size, "session.json");
    Session s;
    try {
        s = morphogen::loadSessionFile(path);
    } catch (const InputError&) {
        return 0;
    } catch (const std::exception& e) {
        fuzz::fail("loadSessionFile threw " + describe(e) + " instead of an InputError");
    }
    plan(s);

    const nlohmann::json written = morphogen::sessionToJson(s);
    const std::string again = fuzz::writeInput(written.dump(2) + "\n", "written.json");
    try {
        const Session back = morphogen::loadSessionFile(again);
        if (morphogen::sessionToJson(back) != written)
            fuzz::fail("the written session reads back differently:\n" + written.dump(2) +
                       "\nread back as\n" + morphogen::sessionToJson(back).dump(2));
    } catch (const std::exception& e) {
        fuzz::fail("an accepted session, written back, is refused: " + describe(e) + "\n" +
                   written.dump(2));
    }
    return 0;
}
