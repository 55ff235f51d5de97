#include "render/shadows/PageAllocator.h"

#include <bit>

#include "core/Error.h"

namespace manylights {

PageAllocator::PageAllocator(int roots, int rootsAcross) : roots_(roots), rootsAcross_(rootsAcross)
{
    ML_ASSERT(roots > 0 && rootsAcross > 0);
    clear();
}

int PageAllocator::orderOf(int side)
{
    ML_ASSERT(side > 0 && side <= kRootPages && std::has_single_bit(static_cast<unsigned>(side)));
    return std::countr_zero(static_cast<unsigned>(side));
}

void PageAllocator::clear()
{
    for (auto& blocks : free_)
        blocks.clear();
    for (int root = 0; root < roots_; ++root)
        free_[kRootOrder].insert({root / rootsAcross_ * kRootPages, root % rootsAcross_ * kRootPages});
    usedPages_ = 0;
}

std::optional<PageBlock> PageAllocator::allocate(int side)
{
    const int order = orderOf(side);
    int found = order;
    while (found <= kRootOrder && free_[static_cast<std::size_t>(found)].empty())
        ++found;
    if (found > kRootOrder)
        return std::nullopt;
    auto [row, column] = *free_[static_cast<std::size_t>(found)].begin();
    free_[static_cast<std::size_t>(found)].erase(free_[static_cast<std::size_t>(found)].begin());
    // Quarter down to the order asked for: the first quarter is cut on, the other three freed.
    for (int o = found; o > order; --o) {
        const int half = 1 << (o - 1);
        auto& quarters = free_[static_cast<std::size_t>(o - 1)];
        quarters.insert({row, column + half});
        quarters.insert({row + half, column});
        quarters.insert({row + half, column + half});
    }
    usedPages_ += static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    return PageBlock{column, row, side};
}

void PageAllocator::free(const PageBlock& block)
{
    int order = orderOf(block.side);
    int row = block.y;
    int column = block.x;
    ML_ASSERT(row % block.side == 0 && column % block.side == 0);
    usedPages_ -= static_cast<std::size_t>(block.side) * static_cast<std::size_t>(block.side);
    // Merge with the three siblings while they are all free.
    while (order < kRootOrder) {
        const int parentSide = 1 << (order + 1);
        const int parentRow = row - row % parentSide;
        const int parentColumn = column - column % parentSide;
        const int half = 1 << order;
        auto& blocks = free_[static_cast<std::size_t>(order)];
        const std::array<std::pair<int, int>, 4> siblings = {{{parentRow, parentColumn},
                                                              {parentRow, parentColumn + half},
                                                              {parentRow + half, parentColumn},
                                                              {parentRow + half, parentColumn + half}}};
        bool allFree = true;
        for (const auto& sibling : siblings)
            if (sibling != std::pair{row, column} && !blocks.contains(sibling))
                allFree = false;
        if (!allFree)
            break;
        for (const auto& sibling : siblings)
            blocks.erase(sibling);
        row = parentRow;
        column = parentColumn;
        ++order;
    }
    free_[static_cast<std::size_t>(order)].insert({row, column});
}

}  // namespace manylights
