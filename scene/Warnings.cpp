#include "scene/Warnings.h"

#include "core/Error.h"

namespace manylights {

void Warnings::add(const std::string& message)
{
    if (strict_)
        throw Error(message);
    messages_.push_back(message);
}

void FileWarnings::note(std::size_t lineNumber, const std::string& kind, const std::string& message)
{
    auto [entry, inserted] = byKind_.try_emplace(kind, Entry{lineNumber, message, 0});
    if (inserted)
        order_.push_back(kind);
    ++entry->second.count;
}

void FileWarnings::flushInto(Warnings& warnings) const
{
    for (const std::string& kind : order_) {
        const Entry& entry = byKind_.at(kind);
        std::string line = displayName_ + ": ";
        if (entry.lineNumber > 0)
            line += "line " + std::to_string(entry.lineNumber) + ": ";
        line += entry.message;
        if (entry.count > 1)
            line += " (and " + std::to_string(entry.count - 1) + (entry.lineNumber > 0 ? " more lines)" : " more)");
        warnings.add(line);
    }
}

}  // namespace manylights
