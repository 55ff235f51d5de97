#include "scene/Warnings.h"

#include "core/Error.h"

namespace manylights {

void Warnings::add(const std::string& message)
{
    if (strict_)
        throw Error(message);
    messages_.push_back(message);
}

}  // namespace manylights
