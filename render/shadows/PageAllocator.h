// Where the shadow-page pool's parts live in its depth atlas (render/shadows/ShadowPool.h): a
// buddy allocator over squares of pages. The atlas is a grid of roots, each a square of
// kRootPages x kRootPages pages (a whole face at the highest level); a block is a square of
// pages a power of two on a side, cut from a larger free block by quartering and merged back
// with its three siblings when all four are free. A block keeps its place while it is
// allocated, so a cached face stays where its depth was drawn. No GL: unit-tested
// (tests/gl/ShadowFacesTest.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <set>
#include <utility>

namespace manylights {

// A square of pages: its first page (column, row in the atlas' grid of pages) and its side.
struct PageBlock {
    int x = 0;
    int y = 0;
    int side = 1;  // pages, a power of two
    friend bool operator==(const PageBlock&, const PageBlock&) = default;
};

class PageAllocator {
public:
    // The largest block: one root.
    static constexpr int kRootOrder = 6;
    static constexpr int kRootPages = 1 << kRootOrder;

    // `roots` roots, all free, placed row by row `rootsAcross` to a row (the last row may be short).
    PageAllocator(int roots, int rootsAcross);

    // A free block of `side` pages on a side (a power of two up to kRootPages), or none where no
    // free block is that large. Of the candidates, the lowest row, then column, first: the same
    // requests in the same order place the same blocks on every run.
    std::optional<PageBlock> allocate(int side);
    // Returns a block allocate() gave.
    void free(const PageBlock& block);
    // Frees every block.
    void clear();

    // The grid's size in pages (rows of whole roots, the last perhaps short of roots).
    int pagesAcross() const { return rootsAcross_ * kRootPages; }
    int pagesDown() const { return (roots_ + rootsAcross_ - 1) / rootsAcross_ * kRootPages; }
    std::size_t capacityPages() const { return static_cast<std::size_t>(roots_) * kRootPages * kRootPages; }
    std::size_t usedPages() const { return usedPages_; }

    // The order of a side: side = 1 << order.
    static int orderOf(int side);

private:
    // The free blocks of each order, as (row, column) of their first page: ordered, so the
    // lowest row, then column, comes first.
    std::array<std::set<std::pair<int, int>>, kRootOrder + 1> free_;
    int roots_;
    int rootsAcross_;
    std::size_t usedPages_ = 0;
};

}  // namespace manylights
