// pbrt-v4's default light sampler ("bvh"; PBR 4th ed. §12.6.3, after Conty Estevez & Kulla 2018): a binary
// tree over the bounded lights, each node holding the LightBounds of the lights below it. A light is picked
// for a receiver by walking down from the root, at each node to one child with probability proportional
// to the children's importance at the receiver (LightBounds::importance), so nearby lights that face the
// receiver are chosen among many far or turned-away ones. Lights without bounds (at infinity) are picked
// apart, uniformly, each as often as the whole tree is.
#pragma once

#include <cstdint>
#include <vector>

#include "illum/light/light.h"
#include "illum/light/light_split.h"

namespace illum {

class BvhLightSampler {
public:
    BvhLightSampler() = default;
    // Lights of zero strength are left out (never picked).
    explicit BvhLightSampler(const std::vector<const Light*>& lights);

    // A light for the receiver ctx and its probability; nullptr when none can reach it.
    const Light* sample(const LightSampleContext& ctx, float u, float* pmf) const;
    // The probability that sample() picks `light` for ctx.
    float pmf(const LightSampleContext& ctx, const Light* light) const;

    std::size_t node_count() const { return nodes_.size(); }
    // The tree's depth (1 for a single leaf, 0 when empty).
    int depth() const;

private:
    static constexpr std::uint32_t kNone = ~std::uint32_t(0);
    struct Node {
        LightBounds bounds;
        PreparedLightBounds prepared; // what sampling evaluates
        // A leaf: the index into lights_. Otherwise the second child (the first follows the node).
        std::uint32_t second_or_light = 0;
        std::uint32_t parent = kNone;
        bool leaf = false;
        // When both children have the same bounds but for phi (the two triangles of a quad), their
        // importances keep the ratio of their phis at every receiver: the chance of the first, fixed at
        // the build. Negative otherwise.
        float fixed_p0 = -1;
    };
    // The chance of the first child of interior node `index` at p, n (0/0: none can reach the receiver).
    float first_child_probability(const Node& node, std::uint32_t index, Point3f p, Normal3f n) const;
    using Item = BoundedLight;
    std::uint32_t build(std::vector<Item>& items, std::size_t begin, std::size_t end, std::uint32_t parent);

    LightSplit split_;                   // the tree holds its bounded lights
    std::vector<const Light*> lights_;   // the tree's, by leaf
    std::vector<Node> nodes_;            // depth first: a node's first child follows it
    std::vector<std::uint32_t> leaf_of_; // by Light::index: its leaf, or kNone
};

} // namespace illum
