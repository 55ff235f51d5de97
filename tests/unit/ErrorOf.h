// The message of the manylights::Error a call throws, for tests of error paths.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"

namespace manylights::test {

// The message of the Error `load` throws; fails the test when it throws none.
template <typename Load>
std::string errorThrownBy(Load load)
{
    try {
        load();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return {};
}

}  // namespace manylights::test
