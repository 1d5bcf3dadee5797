#include "illum/light/bvh_light_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace illum {

namespace {

// The orientation measure of a cone of normals θo widened by the emission spread θe (Conty Estevez &
// Kulla 2018, eq. 1): the solid angle of the normals, 2π (1 - cos θo), plus the spread's band,
//   π/2 (2 θw sin θo - cos(θo - 2 θw) - 2 θo sin θo + cos θo),  θw = min(θo + θe, π).
float orientation_measure(const LightBounds& b) {
    float theta_o = safe_acos(b.cos_theta_o), theta_e = safe_acos(b.cos_theta_e);
    float theta_w = std::min(theta_o + theta_e, kPi);
    float sin_o = safe_sqrt(1 - b.cos_theta_o * b.cos_theta_o);
    return 2 * kPi * (1 - b.cos_theta_o) +
           kPi / 2 *
               (2 * theta_w * sin_o - std::cos(theta_o - 2 * theta_w) - 2 * theta_o * sin_o + b.cos_theta_o);
}

// The cost of a group in a split along axis `dim` of the parent's box (Conty Estevez & Kulla 2018, eq. 2):
// strength × orientation measure × surface area, times the parent box's aspect along dim (splits across
// the box's long side preferred). The area gets the diagonal's square added, so that a group of points
// (zero area: pbrt-v4 costs every split of point lights at zero) still costs by its extent.
float split_cost(const LightBounds& b, const Bounds3f& parent, int dim) {
    if (b.phi == 0) return 0;
    Vector3f d = b.bounds.diagonal(), pd = parent.diagonal();
    float area = 2 * (d.x * d.y + d.y * d.z + d.z * d.x) + length_squared(d);
    float aspect = std::max({pd.x, pd.y, pd.z}) / std::max(pd[dim], 1e-30f);
    return b.phi * orientation_measure(b) * aspect * area;
}

} // namespace

BvhLightSampler::BvhLightSampler(const std::vector<const Light*>& lights) : split_(lights) {
    leaf_of_.assign(split_.index_count(), kNone);
    std::vector<Item> items = std::move(split_.bounded());
    if (items.empty()) return;
    nodes_.reserve(2 * items.size() - 1);
    lights_.reserve(items.size());
    build(items, 0, items.size(), kNone);
    for (Node& node : nodes_) node.prepared = PreparedLightBounds(node.bounds);
}

std::uint32_t BvhLightSampler::build(std::vector<Item>& items, std::size_t begin, std::size_t end,
                                     std::uint32_t parent) {
    std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.push_back(Node{});
    if (end - begin == 1) {
        Node& leaf = nodes_[index];
        leaf.bounds = items[begin].bounds;
        leaf.second_or_light = std::uint32_t(lights_.size());
        leaf.parent = parent;
        leaf.leaf = true;
        leaf_of_[items[begin].light->index] = index;
        lights_.push_back(items[begin].light);
        return index;
    }

    Bounds3f box, centroids;
    for (std::size_t i = begin; i < end; ++i) {
        box.extend(items[i].bounds.bounds);
        centroids.extend(items[i].bounds.bounds.center());
    }
    // Twelve buckets along each axis where the centroids spread; the split between buckets of least cost.
    constexpr int kBuckets = 12;
    float best_cost = std::numeric_limits<float>::infinity();
    int best_dim = -1, best_split = 0;
    auto bucket_of = [&](const Item& item, int dim) {
        float lo = centroids.lo[dim], hi = centroids.hi[dim];
        int b = int(float(kBuckets) * (item.bounds.bounds.center()[dim] - lo) / (hi - lo));
        return std::clamp(b, 0, kBuckets - 1);
    };
    for (int dim = 0; dim < 3; ++dim) {
        if (!(centroids.hi[dim] > centroids.lo[dim])) continue;
        std::array<LightBounds, kBuckets> bucket{};
        for (std::size_t i = begin; i < end; ++i) {
            LightBounds& b = bucket[std::size_t(bucket_of(items[i], dim))];
            b = union_of(b, items[i].bounds);
        }
        for (int split = 0; split < kBuckets - 1; ++split) {
            LightBounds below, above;
            for (int i = 0; i <= split; ++i) below = union_of(below, bucket[std::size_t(i)]);
            for (int i = split + 1; i < kBuckets; ++i) above = union_of(above, bucket[std::size_t(i)]);
            if (below.phi == 0 || above.phi == 0) continue; // an empty side splits nothing
            float cost = split_cost(below, box, dim) + split_cost(above, box, dim);
            if (cost < best_cost) best_cost = cost, best_dim = dim, best_split = split;
        }
    }
    std::size_t mid = (begin + end) / 2;
    if (best_dim >= 0) {
        auto it = std::partition(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end),
                                 [&](const Item& item) { return bucket_of(item, best_dim) <= best_split; });
        std::size_t m = std::size_t(it - items.begin());
        if (m > begin && m < end) mid = m;
    }

    build(items, begin, mid, index);
    std::uint32_t second = build(items, mid, end, index);
    Node& node = nodes_[index];
    const LightBounds &a = nodes_[index + 1].bounds, &b = nodes_[second].bounds;
    node.bounds = union_of(a, b);
    node.second_or_light = second;
    node.parent = parent;
    if (a.bounds.lo == b.bounds.lo && a.bounds.hi == b.bounds.hi && a.w == b.w &&
        a.cos_theta_o == b.cos_theta_o && a.cos_theta_e == b.cos_theta_e && a.two_sided == b.two_sided)
        node.fixed_p0 = a.phi / (a.phi + b.phi);
    return index;
}

float BvhLightSampler::first_child_probability(const Node& node, std::uint32_t index, Point3f p,
                                               Normal3f n) const {
    if (node.fixed_p0 >= 0) return node.fixed_p0;
    float c0, c1;
    importance_pair(nodes_[index + 1].prepared, nodes_[node.second_or_light].prepared, p, n, &c0, &c1);
    return c0 / (c0 + c1);
}

const Light* BvhLightSampler::sample(const LightSampleContext& ctx, float u, float* pmf) const {
    if (const Light* l = split_.pick_unbounded(&u, pmf)) return l;
    if (nodes_.empty()) return nullptr;
    float p = split_.bounded_share();
    std::uint32_t index = 0;
    while (!nodes_[index].leaf) {
        const Node& node = nodes_[index];
        float p0 = first_child_probability(node, index, ctx.p, ctx.n);
        if (!(p0 >= 0)) return nullptr; // 0/0: neither child reaches the receiver
        // Reuse u: rescaled into the chosen child's part of [0, 1).
        if (u < p0) {
            u = std::min(u / p0, 0x1.fffffep-1f);
            p *= p0;
            index = index + 1;
        } else {
            u = std::min((u - p0) / (1 - p0), 0x1.fffffep-1f);
            p *= 1 - p0;
            index = node.second_or_light;
        }
    }
    // A single bounded light (the root a leaf) is picked whatever its importance: where that is zero the
    // light cannot reach the receiver and adds nothing, and pmf() agrees without evaluating it either.
    *pmf = p;
    return lights_[nodes_[index].second_or_light];
}

float BvhLightSampler::pmf(const LightSampleContext& ctx, const Light* light) const {
    if (std::optional<float> p = split_.unbounded_pmf(light)) return *p;
    if (!light || light->index >= leaf_of_.size()) return 0;
    std::uint32_t index = leaf_of_[light->index];
    if (index == kNone) return 0;
    float p = split_.bounded_share();
    if (index == 0) return p;
    // Up from the leaf: at each parent, the chance of the child on the way.
    while (nodes_[index].parent != kNone) {
        std::uint32_t parent = nodes_[index].parent;
        float p0 = first_child_probability(nodes_[parent], parent, ctx.p, ctx.n);
        float c = index == parent + 1 ? p0 : 1 - p0;
        if (!(c > 0)) return 0; // also 0/0: neither child reaches the receiver
        p *= c;
        index = parent;
    }
    return p;
}

int BvhLightSampler::depth() const {
    int deepest = 0;
    for (std::uint32_t leaf : leaf_of_) {
        if (leaf == kNone) continue;
        int d = 1;
        for (std::uint32_t i = leaf; nodes_[i].parent != kNone; i = nodes_[i].parent) ++d;
        deepest = std::max(deepest, d);
    }
    return deepest;
}

} // namespace illum
