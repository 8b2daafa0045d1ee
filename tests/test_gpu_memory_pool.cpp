// Device memory: small buffers share blocks (gpu::MemoryPool), so that a scene of many objects stays far from
// the device's limit on allocations (4096 on some drivers), and each buffer still holds its own bytes.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/memory_pool.hpp"
#include "gpu/resources.hpp"
#include "mesh/primitives.hpp"
#include "render/stipple_renderer.hpp"
#include "stipple/object_data.hpp"
#include "stipple/stipple_set.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"

namespace stipple {
namespace {

using gpu::Buffer;
using gpu::MemoryUse;

class MemoryPool : public test::GpuTest {};

uint8_t pattern(size_t buffer, size_t byte) { return uint8_t(buffer * 131 + byte * 7 + (byte >> 8)); }

TEST_F(MemoryPool, SmallBuffersShareBlocksAndKeepTheirOwnBytes) {
    gpu::MemoryPool& pool = context->memory_pool();
    const uint32_t allocations_before = pool.allocation_count();
    const uint64_t bytes_before = context->bytes_allocated();
    constexpr size_t kBuffers = 300;
    std::vector<Buffer> uploads, devices;
    std::vector<size_t> sizes;
    for (size_t i = 0; i < kBuffers; ++i) {
        sizes.push_back(4 + (i * 937) % 5000);  // 4 bytes to 5 KB, no two neighbours alike
        uploads.emplace_back(*context, sizes[i], VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
        devices.emplace_back(*context, sizes[i], VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal);
    }
    // 600 buffers of 1.5 MB in all: one block per kind of memory, where each had an allocation of its own.
    const uint32_t shared = pool.allocation_count() - allocations_before;
    std::printf("%zu small buffers: %u allocations, %.2f MiB\n", 2 * kBuffers, shared,
                double(context->bytes_allocated() - bytes_before) / 1048576.0);
    EXPECT_LE(shared, 4u);
    for (size_t i = 0; i < kBuffers; ++i) {
        auto* bytes = static_cast<uint8_t*>(uploads[i].mapped());
        ASSERT_NE(bytes, nullptr);
        for (size_t b = 0; b < sizes[i]; ++b) bytes[b] = pattern(i, b);
        uploads[i].flush();
    }
    VkCommandBuffer cb = context->begin_one_shot();
    for (size_t i = 0; i < kBuffers; ++i) {
        const VkBufferCopy region{0, 0, sizes[i]};
        vkCmdCopyBuffer(cb, uploads[i].handle(), devices[i].handle(), 1, &region);
    }
    context->submit_and_wait(cb);
    // Each buffer reads back its own pattern, in full: no range overlaps another, mapped or on the device.
    size_t wrong = 0;
    for (size_t i = 0; i < kBuffers; ++i) {
        const std::vector<std::byte> back = gpu::read_buffer(*context, devices[i], sizes[i]);
        const auto* mapped = static_cast<const uint8_t*>(uploads[i].mapped());
        for (size_t b = 0; b < sizes[i]; ++b)
            wrong += uint8_t(back[b]) != pattern(i, b) || mapped[b] != pattern(i, b);
    }
    EXPECT_EQ(wrong, 0u);

    // A large buffer gets an allocation of its own.
    const uint32_t before_large = pool.allocation_count();
    Buffer large(*context, 4 * gpu::MemoryPool::kLargestShared, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal);
    EXPECT_EQ(pool.allocation_count(), before_large + 1);

    // All given back: the blocks are freed with their last buffer.
    uploads.clear(), devices.clear(), large.reset();
    EXPECT_EQ(pool.allocation_count(), allocations_before);
    EXPECT_EQ(context->bytes_allocated(), bytes_before);
}

TEST_F(MemoryPool, FreedNeighboursJoinForALargerBuffer) {
    gpu::MemoryPool& pool = context->memory_pool();
    const uint32_t allocations_before = pool.allocation_count();
    constexpr VkDeviceSize kPiece = 100 * 1024;  // two of them hold a largest shared buffer, one does not
    static_assert(kPiece < gpu::MemoryPool::kLargestShared && 2 * kPiece > gpu::MemoryPool::kLargestShared);
    auto piece = [&] { return Buffer(*context, kPiece, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal); };
    // Fill the first block and the second, stopping where a third would begin.
    std::vector<Buffer> pieces;
    while (pool.allocation_count() < allocations_before + 3) pieces.push_back(piece());
    pieces.pop_back();  // the third block, freed with its only buffer
    ASSERT_EQ(pool.allocation_count(), allocations_before + 2);
    ASSERT_GE(pieces.size(), 30u);
    {  // Both blocks are full: another piece needs a block of its own.
        const Buffer more = piece();
        EXPECT_EQ(pool.allocation_count(), allocations_before + 3);
    }
    // Two neighbours of the first block freed (the block was filled from its start, one after the other): the
    // largest shared buffer fits in their joined range, and in neither alone.
    pieces[1].reset(), pieces[2].reset();
    const Buffer joined(*context, gpu::MemoryPool::kLargestShared, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal);
    EXPECT_EQ(pool.allocation_count(), allocations_before + 2);
}

// A crowd of copies of one small model: a copy's buffers, a score of them, share blocks. (A copy's lists of
// the density paths are sized for all its candidates: from 128 KiB on, about 16k candidates, three of them
// take allocations of their own.)
TEST_F(MemoryPool, ACrowdOfCopiesHoldsFewAllocations) {
    const Mesh mesh = make_icosphere(2);
    ObjectParams params;
    params.generation.dmax = 0.01f;
    const StippleSet stipples = generate_stipples(mesh, params.generation);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(mesh, stipples, glm::mat4(1.0f), params);
    const uint32_t one = context->memory_pool().allocation_count();
    constexpr int kCopies = 60;
    for (int i = 1; i < kCopies; ++i)
        renderer.add_object(mesh, stipples, glm::translate(glm::mat4(1.0f), glm::vec3(2.5f * float(i), 0.0f, 0.0f)), params);
    const uint32_t crowd = context->memory_pool().allocation_count();
    std::printf("one object: %u allocations; %d copies: %u (%.2f a copy)\n", one, kCopies, crowd,
                double(crowd - one) / (kCopies - 1));
    // With an allocation a buffer a copy held about 20.
    EXPECT_LT(crowd - one, uint32_t(kCopies - 1)) << "under one allocation a copy";
}

}  // namespace
}  // namespace stipple
