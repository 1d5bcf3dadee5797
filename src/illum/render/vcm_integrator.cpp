#include "illum/render/vcm_integrator.h"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <vector>

#include "illum/camera/film.h"
#include "illum/camera/splat_film.h"
#include "illum/medium/entry_medium.h"
#include "illum/render/light_vertex_grid.h"
#include "illum/render/path_vertex.h"
#include "illum/render/render_arena.h"
#include "illum/render/vcm_mis.h"
#include "illum/util/error.h"
#include "illum/util/line_aligned.h"
#include "illum/util/progress.h"

namespace illum {

namespace {

constexpr std::size_t kChunk = 1024; // light subpaths or pixels per task

// A light subpath vertex kept for the iteration: the path vertex without its BSDF (rebuilt from the hit
// when a connection needs it), its weights' densities and where it sits in its subpath.
struct StoredVertex {
    PathVertex v;
    MisVertex mis;
    float tail = 0; // subpath_tails at this vertex (vcm_mis.h), for this iteration's techniques
    std::uint32_t path = 0;
    std::uint32_t index = 0; // 0: the vertex on the light
    bool terminated = false; // the subpath's secondary wavelengths were terminated (dispersion)
    // A vertex in a textured subsurface shape's medium, evaluated where the subpath entered (entry_medium.h;
    // in the arena while the subpath was traced): its copy's index in the chunk's `entered`, for v.medium
    // (a medium vertex) or v.hit.medium (a surface vertex). -1: none.
    std::int32_t entered = -1;
};

// One chunk of light subpaths: its vertices (subpaths in order) and its light-tracing splats.
struct LightChunk {
    // Written by one thread while the others write their chunks: in lines of their own (line_aligned.h).
    LineAlignedVector<StoredVertex> vertices;
    LineAlignedVector<std::uint32_t> path_begin; // subpath p0 + i starts at vertices[path_begin[i]]
    LineAlignedVector<Splat> splats;
    LineAlignedVector<EntryMedium> entered; // the entered media of its vertices (StoredVertex::entered)
    int dropped = 0;
};

// What a merge reads of a stored light vertex y_j (j >= 1) and of its predecessors, packed into 80 bytes in
// the grid's cell order, so that a candidate found in the grid costs one or two cache lines instead of
// the several 440-byte StoredVertex records (y_j, y_{j-1}, y_{j-2}, the light vertex) it would touch.
struct MergeVertex {
    SampledSpectrum beta;     // y_j's throughput
    Vector3f wo;              // unit direction from y_j towards y_{j-1}
    float pdf_fwd = 0;        // y_j's own density
    DensityTarget prev;       // y_{j-1}, where the camera vertex's reverse density is converted
    MisVertex prev_mis;       // y_{j-1}'s weights' densities
    float prev2_tail = 0;     // y_{j-2}'s subpath_tails (j >= 2)
    bool prev2_delta = false; // y_{j-2} was scattered specularly (j >= 2)
    bool light_delta = false; // y_0 is a delta light
    bool terminated = false;  // StoredVertex::terminated
    std::uint8_t j = 0;
};

static_assert(sizeof(MergeVertex) <= 80);

MergeVertex merge_vertex(const StoredVertex& y) {
    const StoredVertex& prev = (&y)[-1];
    MergeVertex m;
    m.beta = y.v.beta;
    m.wo = y.v.wo;
    m.pdf_fwd = y.v.pdf_fwd;
    m.prev = density_target(prev.v);
    m.prev_mis = prev.mis;
    if (y.index >= 2) {
        m.prev2_tail = (&y)[-2].tail;
        m.prev2_delta = (&y)[-2].mis.delta;
    }
    m.light_delta = (&y - y.index)->v.is_delta_light();
    m.terminated = y.terminated;
    m.j = std::uint8_t(y.index);
    return m;
}

MisVertex mis_of(const PathVertex& v) {
    MisVertex m;
    m.fwd = v.pdf_fwd;
    m.rev = v.pdf_rev;
    m.delta = v.delta;
    m.nonspecular = v.type == VertexType::Surface && v.bsdf && v.bsdf.is_non_specular();
    return m;
}

// The base-3 radical inverse of i (the iterations' wavelengths, as pbrt-v4's SPPM).
double radical_inverse_3(std::uint32_t i) {
    double inv = 1.0 / 3, f = inv, v = 0;
    for (; i > 0; i /= 3, f *= inv) v += f * double(i % 3);
    return v;
}

// Per-thread scratch: a camera subpath, the paired light subpath, and their weights' densities.
struct Scratch {
    LineAlignedVector<PathVertex> camera, light;
    LineAlignedVector<MisVertex> cmis, lmis, tmp_c, tmp_l;
    LineAlignedVector<float> ctail, ltail, mtail; // mtail: a merged subpath's tail
    PathVertex sampled;                           // the light point next-event estimation samples (s = 1)
    explicit Scratch(int max_depth) {
        camera.resize(std::size_t(max_depth) + 2);
        light.resize(std::size_t(max_depth) + 1);
        cmis.resize(camera.size());
        tmp_c.resize(camera.size());
        lmis.resize(light.size());
        tmp_l.resize(light.size() + 1);
        ctail.resize(camera.size());
        ltail.resize(light.size());
        mtail.resize(light.size());
    }
};

float pow_beta(float x, float beta) { return beta == 2 ? x * x : x; }

// The densities of the vertices next to a join between lv[s-1] and cv[t-1] as they are in the joined path
// (Veach eq. 10.9's reverse densities, as bdpt_integrator.cpp's mis_weight), written into the weights'
// copies ml (s entries) and mc (t entries), and the joint's ends made non-delta.
// at_qs / at_pt: the ends' scattering towards each other where the connection evaluated it.
void set_join_densities(const PathContext& ctx, const PathVertex* lv, int s, const PathVertex* cv, int t,
                        MisVertex* ml, MisVertex* mc, const EndScattering* at_qs = nullptr,
                        const EndScattering* at_pt = nullptr) {
    const PathVertex* qs = s > 0 ? &lv[s - 1] : nullptr;
    const PathVertex* pt = t > 0 ? &cv[t - 1] : nullptr;
    const PathVertex* qs_m = s > 1 ? &lv[s - 2] : nullptr;
    const PathVertex* pt_m = t > 1 ? &cv[t - 2] : nullptr;
    const JoinDensities j = join_densities(ctx, qs, qs_m, *pt, pt_m, at_qs, at_pt);
    mc[t - 1].rev = j.pt_rev;
    mc[t - 1].delta = false;
    if (pt_m) mc[t - 2].rev = j.pt_m_rev;
    if (qs) {
        ml[s - 1].rev = j.qs_rev;
        ml[s - 1].delta = false;
    }
    if (qs_m) ml[s - 2].rev = j.qs_m_rev;
}

class VcmRender {
public:
    VcmRender(const Scene& scene, const VcmSettings& settings, int max_depth, long long light_paths,
              float radius0, const RenderOptions& options)
        : scene_(scene), settings_(settings), max_depth_(max_depth), n_light_(std::size_t(light_paths)),
          radius0_(radius0), options_(options), w_(scene.width), h_(scene.height),
          pixels_(std::size_t(scene.width) * std::size_t(scene.height)), film_(w_, h_),
          splat_film_(w_, h_, *scene.filter) {
        scene.accelerator.bounds().bounding_sphere(&scene_center_, &scene_radius_);
        camera_delta_ = dynamic_cast<const OrthographicCamera*>(scene.camera.get()) != nullptr;
        techniques_.vc = settings.mode != VcmSettings::Mode::VM;
        techniques_.vm = settings.mode != VcmSettings::Mode::VC;
        techniques_.n_lt = float(double(n_light_) / double(pixels_));
        techniques_.power = settings.power_heuristic ? 2.0f : 1.0f;
        light_chunks_.resize((n_light_ + kChunk - 1) / kChunk);
    }
    RenderResult run(VcmStats* stats);

private:
    void light_pass(int sample_index, tbb::task_arena& arena);
    void trace_light(std::size_t p, int sample_index, ThreadContext& tc, Scratch& sc, LightChunk& out);
    // Motion blur: the time of light subpath p and of the camera subpaths paired with it (their connections
    // join the two at one instant), uniform in the shutter interval from a hash of p and the iteration. A
    // merge joins a camera subpath with other light subpaths' vertices, found at their own times (as SPPM's
    // photons are, and pbrt-v4's).
    float path_time(std::size_t p, int sample_index) const {
        if (!scene_.has_motion) return 0;
        std::uint64_t h = hash(std::uint64_t(p), std::uint32_t(sample_index), std::uint32_t(0x7713u));
        return scene_.sample_time(float(h >> 40) * 0x1p-24f);
    }
    void build_grid();
    void camera_pass(int sample_index, tbb::task_arena& arena);
    void trace_camera(int x, int y, int sample_index, ThreadContext& tc, Scratch& sc, std::uint64_t* merges,
                      int* dropped);
    SampledSpectrum connect(const PathContext& ctx, Scratch& sc, int s, int t, bool light0_delta,
                            int ch) const;
    // Returns the merges with subpaths of all wavelengths; those with subpaths whose secondary wavelengths
    // were terminated go to *terminated instead.
    SampledSpectrum merge(const PathContext& ctx, Scratch& sc, int t, SampledSpectrum* terminated,
                          std::uint64_t* merges, int* dropped) const;
    Image image(int passes) const;

    const Scene& scene_;
    VcmSettings settings_;
    int max_depth_;
    std::size_t n_light_;
    float radius0_;
    RenderOptions options_;
    int w_, h_;
    std::size_t pixels_;
    Film film_;
    SplatFilm splat_film_;
    Point3f scene_center_;
    float scene_radius_ = 0;
    bool camera_delta_ = false;
    MisTechniques techniques_;

    // This iteration's state.
    SampledWavelengths lambda_;
    float radius_ = 0;
    std::vector<LightChunk> light_chunks_;
    std::vector<Point3f> grid_p_;
    std::vector<const StoredVertex*> grid_sv_; // the mergeable vertices, in the chunks' order
    std::vector<std::uint32_t> grid_order_;    // LightVertexGrid::number_by_cell
    std::vector<MergeVertex> grid_v_;          // what merges read of them, in the grid's cell order
    LightVertexGrid grid_;

    std::unique_ptr<tbb::enumerable_thread_specific<ThreadContext>> contexts_;
    std::unique_ptr<tbb::enumerable_thread_specific<Scratch>> scratch_;
    std::vector<std::uint64_t> merges_per_chunk_;
    std::vector<int> dropped_per_chunk_;
    std::uint64_t merges_ = 0, dropped_ = 0;
    std::size_t grid_bytes_ = 0;
};

// (a) Light subpath p of the iteration: traced, stored, and connected to the camera (t = 1).
void VcmRender::trace_light(std::size_t p, int sample_index, ThreadContext& tc, Scratch& sc,
                            LightChunk& out) {
    Sampler& sampler = tc.sampler;
    // Light subpaths draw from "pixels" below the image (y < 0), so they never share a camera path's stream.
    sampler.start_pixel_sample({int(p % std::size_t(w_)), -1 - int(p / std::size_t(w_))}, sample_index);
    tc.arena.reset();
    tc.lambda = lambda_;
    out.path_begin.push_back(std::uint32_t(out.vertices.size()));
    const int ch = std::min(kSpectrumSamples - 1, int(sampler.get_1d() * kSpectrumSamples));
    PCG32 rng;
    {
        float a = sampler.get_1d(), b = sampler.get_1d();
        rng.set_sequence(hash(std::uint32_t(a * 0x1p32f), std::uint32_t(b * 0x1p32f)));
    }
    PathContext ctx{scene_, tc, rng, scene_radius_, path_time(p, sample_index)};
    PathVertex* lv = sc.light.data();
    float u_light = sampler.get_1d();
    Point2f u_pos = sampler.get_2d(), u_dir = sampler.get_2d();
    int n = trace_light_subpath(ctx, u_light, u_pos, u_dir, max_depth_, ch, lv);
    if (n == 0) return;
    const bool terminated = tc.lambda.secondary_terminated();
    for (int i = 0; i < n; ++i) sc.lmis[std::size_t(i)] = mis_of(lv[i]);
    const bool light0_delta = lv[0].is_delta_light();
    subpath_tails(sc.lmis.data(), n, false, light0_delta, techniques_, sc.ltail.data());

    // Light tracing (VC with t = 1, Veach §10.2): L = β f*(ω_o → ω_c) |cos θ| W_e / p_ω at the lens point
    // from camera.sample_wi, splatted where it lands; scaled by N_pixels / N_light so that the splat film's
    // normalisation (one particle per pixel) holds.
    const bool lt = techniques_.vc && !camera_delta_;
    const float splat_scale = float(double(pixels_) / double(n_light_));
    for (int s = 2; lt && s <= n; ++s) {
        const PathVertex& qs = lv[s - 1];
        Point2f u = sampler.get_2d_if(scene_.camera->uses_lens_sample());
        if (!qs.is_connectible()) continue;
        std::optional<CameraWiSample> cs = scene_.camera_sample_wi(qs.p, u, ctx.time);
        if (!cs) continue;
        PathVertex cam;
        cam.type = VertexType::Camera;
        cam.p = cs->p_lens;
        cam.medium = scene_.camera_medium;
        cam.beta = SampledSpectrum((cs->we / cs->pdf).value);
        const Segment to_camera = segment(qs, cam);
        if (!(to_camera.inv_d2 > 0)) continue;
        const EndScattering at_qs = end_scattering(qs, to_camera.w, TransportMode::Importance);
        SampledSpectrum l = qs.beta * at_qs.f * cam.beta;
        if (qs.on_surface()) l *= std::abs(dot(cs->wi, Vector3f(qs.ns)));
        if (l.is_black()) continue;
        l *= connection_transmittance(ctx, qs, cam, ch);
        if (l.is_black()) continue;
        std::copy(sc.lmis.begin(), sc.lmis.begin() + s, sc.tmp_l.begin());
        MisVertex mc;
        mc.delta = camera_delta_;
        set_join_densities(ctx, lv, s, &cam, 1, sc.tmp_l.data(), &mc, &at_qs);
        float sum = technique_sum(sc.tmp_l.data(), s, &mc, 1, light0_delta, techniques_, sc.ltail.data());
        float wt = sum > 0 ? connection_term(sc.tmp_l.data(), s, &mc, 1, techniques_) / sum : 0.0f;
        SampledSpectrum c = l * (wt * splat_scale);
        if (!c.is_finite() || c.has_negative()) {
            ++out.dropped;
            continue;
        }
        if (!c.is_black())
            out.splats.push_back({cs->p_raster, scene_.sensor.to_film(Radiance3(c), tc.lambda)});
    }

    // Stored without their BSDFs (which live in this thread's arena only until the next subpath).
    for (int i = 0; i < n; ++i) {
        StoredVertex sv;
        sv.v = lv[i];
        sv.v.bsdf = BSDF();
        sv.mis = sc.lmis[std::size_t(i)];
        sv.tail = sc.ltail[std::size_t(i)];
        sv.path = std::uint32_t(p);
        sv.index = std::uint32_t(i);
        sv.terminated = terminated;
        const Medium* m = sv.v.type == VertexType::Surface ? sv.v.hit.medium : sv.v.medium;
        if (m && m->entered_from()) [[unlikely]] {
            sv.entered = std::int32_t(out.entered.size());
            out.entered.push_back(static_cast<const EntryMedium&>(*m));
        }
        out.vertices.push_back(sv);
    }
}

void VcmRender::light_pass(int sample_index, tbb::task_arena& arena) {
    arena.execute([&] {
        tbb::parallel_for(std::size_t(0), light_chunks_.size(), [&](std::size_t c) {
            LightChunk& out = light_chunks_[c];
            out.vertices.clear();
            out.path_begin.clear();
            out.splats.clear();
            out.entered.clear();
            out.dropped = 0;
            ThreadContext& tc = contexts_->local();
            Scratch& sc = scratch_->local();
            const std::size_t p1 = std::min(n_light_, (c + 1) * kChunk);
            for (std::size_t p = c * kChunk; p < p1; ++p) trace_light(p, sample_index, tc, sc, out);
            out.path_begin.push_back(std::uint32_t(out.vertices.size()));
            tc.arena.reset();
        });
    });
    // In chunk order: the image does not depend on which thread traced what.
    for (const LightChunk& c : light_chunks_) {
        for (const Splat& s : c.splats) splat_film_.add_splat(s);
        dropped_ += std::uint64_t(c.dropped);
    }
}

// (b) The grid of the mergeable light vertices y_j, j >= 1 (the light subpaths hold up to maxdepth + 1).
void VcmRender::build_grid() {
    grid_p_.clear();
    grid_sv_.clear();
    if (techniques_.vm)
        for (const LightChunk& c : light_chunks_)
            for (const StoredVertex& sv : c.vertices)
                if (sv.index >= 1 && sv.mis.mergeable()) {
                    grid_p_.push_back(sv.v.p);
                    grid_sv_.push_back(&sv);
                }
    grid_.build(grid_p_, radius_);
    grid_.number_by_cell(&grid_order_);
    grid_v_.resize(grid_order_.size());
    for (std::size_t k = 0; k < grid_order_.size(); ++k) grid_v_[k] = merge_vertex(*grid_sv_[grid_order_[k]]);
    grid_bytes_ = std::max(grid_bytes_, grid_.memory_bytes() + grid_p_.capacity() * sizeof(Point3f) +
                                            grid_sv_.capacity() * sizeof(const StoredVertex*) +
                                            grid_order_.capacity() * sizeof(std::uint32_t) +
                                            grid_v_.capacity() * sizeof(MergeVertex));
}

// VC strategy (s, t >= 2) between the camera subpath and its paired light subpath (sc.light): its
// MIS-weighted contribution (bdpt_integrator.cpp's connect, with VCM's weights).
SampledSpectrum VcmRender::connect(const PathContext& ctx, Scratch& sc, int s, int t, bool light0_delta,
                                   int ch) const {
    PathVertex* lv = sc.light.data();
    PathVertex* cv = sc.camera.data();
    Sampler& sampler = ctx.tc.sampler;
    if (s != 0 && cv[t - 1].type == VertexType::Light) return SampledSpectrum(0.0f);
    SampledSpectrum l(0.0f);
    PathVertex& sampled = sc.sampled;
    bool have_sampled = false;
    EndScattering at_qs, at_pt; // what connect evaluates at the ends (none: has_pdfs false)
    if (s == 0) {
        const PathVertex& pt = cv[t - 1];
        if (pt.is_light()) l = vertex_le(ctx, pt, cv[t - 2]) * pt.beta;
    } else if (s == 1) {
        // Next-event estimation: a light point sampled from pt (sample_li).
        const PathVertex& pt = cv[t - 1];
        float u_light = sampler.get_1d();
        Point2f u = sampler.get_2d();
        if (!pt.is_connectible()) return SampledSpectrum(0.0f);
        if (!connect_sampled_light(ctx, pt, u_light, u, ch, &sampled, &l, &at_pt))
            return SampledSpectrum(0.0f);
        have_sampled = true;
    } else {
        const PathVertex& qs = lv[s - 1];
        const PathVertex& pt = cv[t - 1];
        if (!qs.is_connectible() || !pt.is_connectible()) return SampledSpectrum(0.0f);
        const Segment joint = segment(qs, pt);
        if (!(joint.inv_d2 > 0)) return SampledSpectrum(0.0f);
        at_qs = end_scattering(qs, joint.w, TransportMode::Importance);
        at_pt = end_scattering(pt, -joint.w, TransportMode::Radiance);
        l = qs.beta * at_qs.f * at_pt.f * pt.beta;
        if (!l.is_black()) l *= connect_g(ctx, qs, pt, joint, ch);
    }
    if (l.is_black()) return l;

    // The weight, with the sampled light point standing in for lv[0] (s = 1).
    MisVertex* ml = sc.tmp_l.data();
    MisVertex* mc = sc.tmp_c.data();
    std::copy(sc.cmis.begin(), sc.cmis.begin() + t, mc);
    bool delta0 = light0_delta;
    if (have_sampled) {
        ml[0] = mis_of(sampled);
        delta0 = sampled.is_delta_light();
        set_join_densities(ctx, &sampled, 1, cv, t, ml, mc, nullptr, &at_pt);
    } else {
        std::copy(sc.lmis.begin(), sc.lmis.begin() + s, ml);
        if (s == 0) delta0 = false; // an emitter that was hit has an area
        set_join_densities(ctx, lv, s, cv, t, ml, mc, &at_qs, &at_pt);
    }
    float sum = technique_sum(ml, s, mc, t, delta0, techniques_, have_sampled ? nullptr : sc.ltail.data(),
                              sc.ctail.data());
    float w = sum > 0 ? connection_term(ml, s, mc, t, techniques_) / sum : 0.0f;
    return l * w;
}

// VM at camera vertex cv[t-1] (a non-specular surface): every stored light vertex y_j within the radius,
//   L = β_cam f(ω_o, ω_y) β_y / (N π r²)   (paper eq. 9 with the uniform kernel),
// weighted by p_VM(j) / Σ: the merged path is y_0..y_j (with z = cv[t-1] in y_j's place) joined to
// cv[t-2..0], i.e. VC(j + 1, t - 1) with p←(y_j) the camera's density of z.
SampledSpectrum VcmRender::merge(const PathContext& ctx, Scratch& sc, int t, SampledSpectrum* terminated,
                                 std::uint64_t* merges, int* dropped) const {
    const PathVertex* cv = sc.camera.data();
    const PathVertex& z = cv[t - 1];
    const float r2 = radius_ * radius_;
    const float kernel = 1 / (float(n_light_) * kPi * r2);
    // The merged path has j + t vertices: depth j + t - 2 <= maxdepth.
    const int j_max = max_depth_ + 2 - t;
    if (j_max < 1) return SampledSpectrum(0.0f);
    // The camera side's densities, the same for every y: cv[t-3]'s reverse density through z.
    MisVertex* mc = sc.tmp_c.data();
    std::copy(sc.cmis.begin(), sc.cmis.begin() + (t - 1), mc);
    if (t >= 3) mc[t - 3].rev = vertex_pdf(ctx, cv[t - 2], &z, cv[t - 3]);
    const float p_cam_z = z.pdf_fwd;
    SampledSpectrum sum_l(0.0f), sum_l_terminated(0.0f);
    *terminated = SampledSpectrum(0.0f);
    // cv[t-2], the vertex z was entered from: the same for every y.
    const Segment to_pred = segment(z.p, cv[t - 2].p);
    grid_.for_within(z.p, [&](std::uint32_t gi) {
        const MergeVertex& y = grid_v_[gi];
        const int j = int(y.j);
        if (j > j_max) return;
        ++*merges;
        SampledSpectrum f = z.bsdf.f(z.wo, y.wo, TransportMode::Radiance).s;
        if (f.is_black()) return;
        // The light side: y_0..y_{j-1} as stored, y_j = z reached from y_{j-1}. technique_sum reads
        // ml[j], ml[j-1] and ml[j-2]'s delta; the terms beyond come from y_{j-2}'s tail.
        MisVertex* ml = sc.tmp_l.data();
        const Segment to_prev = segment(z.p, y.prev.p); // z towards y_{j-1}
        // Both densities below are 0 where z coincides with either neighbour (vertex_pdf's rule).
        const bool apart = to_prev.inv_d2 > 0 && to_pred.inv_d2 > 0;
        if (j >= 2) {
            ml[j - 2] = MisVertex{};
            ml[j - 2].delta = y.prev2_delta;
            sc.mtail[std::size_t(j - 2)] = y.prev2_tail;
        }
        ml[j - 1] = y.prev_mis;
        ml[j - 1].rev = apart ? vertex_pdf(ctx, z, to_pred.w, to_prev.w, y.prev, to_prev.inv_d2) : 0.0f;
        ml[j].fwd = y.pdf_fwd;
        ml[j].rev = p_cam_z;
        ml[j].delta = false;
        ml[j].nonspecular = true;
        MisVertex saved = mc[t - 2];
        mc[t - 2].rev = apart ? vertex_pdf(ctx, z, to_prev.w, to_pred.w, cv[t - 2], to_pred.inv_d2) : 0.0f;
        float sum =
            technique_sum(ml, j + 1, mc, t - 1, y.light_delta, techniques_, sc.mtail.data(), sc.ctail.data());
        mc[t - 2] = saved;
        // p←(y_j) is a delta (0, remapped to 1) after a specular camera vertex, as in the sum.
        float w =
            sum > 0 ? pow_beta((p_cam_z != 0 ? p_cam_z : 1.0f) * techniques_.eta_vcm, techniques_.power) / sum
                    : 0.0f;
        SampledSpectrum c = z.beta * f * y.beta * (w * kernel);
        if (!c.is_finite() || c.has_negative()) {
            ++*dropped;
            return;
        }
        (y.terminated ? sum_l_terminated : sum_l) += c;
    });
    *terminated = sum_l_terminated;
    return sum_l;
}

// (c) The camera subpath of pixel (x, y): VC with its paired light subpath, VM at its vertices.
void VcmRender::trace_camera(int x, int y, int sample_index, ThreadContext& tc, Scratch& sc,
                             std::uint64_t* merges, int* dropped) {
    Sampler& sampler = tc.sampler;
    const Camera& camera = *scene_.camera;
    const bool spectral = options_.spectral;
    sampler.start_pixel_sample({x, y}, sample_index);
    tc.arena.reset();
    FilterSample fs = scene_.filter->sample(sampler.get_pixel_2d());
    Point2f p_film{float(x) + 0.5f + fs.offset.x, float(y) + 0.5f + fs.offset.y};
    Point2f u_lens = sampler.get_2d_if(camera.uses_lens_sample());
    tc.lambda = lambda_;
    if (spectral && camera.is_dispersive()) tc.lambda.terminate_secondary();
    std::optional<CameraRay> cr = camera.generate_ray(p_film, u_lens, spectral ? tc.lambda.hero() : kDLineNm);
    // The paired light subpath, p mod N (below).
    const std::size_t q = (std::size_t(y) * std::size_t(w_) + std::size_t(x)) % n_light_;
    if (cr && scene_.has_motion) cr->ray = scene_.camera_ray_at(cr->ray, path_time(q, sample_index));
    const int ch = std::min(kSpectrumSamples - 1, int(sampler.get_1d() * kSpectrumSamples));
    PCG32 rng;
    {
        float a = sampler.get_1d(), b = sampler.get_1d();
        rng.set_sequence(hash(std::uint32_t(a * 0x1p32f), std::uint32_t(b * 0x1p32f)));
    }
    if (!cr) {
        film_.add_sample(x, y, Color3(0.0f), fs.weight);
        return;
    }
    PathContext ctx{scene_, tc, rng, scene_radius_, cr->ray.time};
    PathVertex* cv = sc.camera.data();
    cv[0] = PathVertex{};
    cv[0].type = VertexType::Camera;
    cv[0].p = cr->ray.o;
    cv[0].medium = scene_.camera_medium;
    cv[0].beta = SampledSpectrum(cr->weight);
    cv[0].delta = camera_delta_;
    Ray ray = cr->ray;
    ray.medium = scene_.camera_medium;
    const float pdf_dir = scene_.camera_pdf_we(ray).dir.value;
    const int n_camera =
        1 + walk(ctx, ray, cv[0].beta, pdf_dir, max_depth_ + 1, TransportMode::Radiance, ch, cv + 1);
    for (int i = 0; i < n_camera; ++i) sc.cmis[std::size_t(i)] = mis_of(cv[i]);
    subpath_tails(sc.cmis.data(), n_camera, true, false, techniques_, sc.ctail.data());

    // The paired light subpath, its BSDFs rebuilt from the stored hits.
    const LightChunk& chunk = light_chunks_[q / kChunk];
    const std::size_t qi = q % kChunk;
    const std::uint32_t b0 = chunk.path_begin[qi], b1 = chunk.path_begin[qi + 1];
    const int n_light = int(b1 - b0);
    bool light_terminated = false;
    for (int i = 0; i < n_light; ++i) {
        const StoredVertex& sv = chunk.vertices[b0 + std::uint32_t(i)];
        PathVertex& v = sc.light[std::size_t(i)];
        v = sv.v;
        if (sv.entered >= 0) [[unlikely]]
            (v.type == VertexType::Surface ? v.hit.medium : v.medium) =
                &chunk.entered[std::size_t(sv.entered)];
        if (v.type == VertexType::Surface) {
            SampledWavelengths lambda = lambda_;
            v.bsdf = v.hit.material->bsdf(v.hit, lambda, tc.arena);
        }
        sc.lmis[std::size_t(i)] = sv.mis;
        sc.ltail[std::size_t(i)] = sv.tail;
        light_terminated = sv.terminated;
    }
    const bool light0_delta = n_light > 0 && sc.light[0].is_delta_light();

    // VC: every strategy with t >= 2 (t = 1 was the light pass's); with merging only, the emitter hits.
    SampledSpectrum l_own(0.0f), l_joined(0.0f), l_merged_terminated(0.0f);
    for (int t = 2; t <= n_camera; ++t) {
        const int s_max = techniques_.vc ? std::min(n_light, max_depth_ + 2 - t) : 0;
        for (int s = 0; s <= s_max; ++s) {
            SampledSpectrum c = connect(ctx, sc, s, t, light0_delta, ch);
            if (c.is_black()) continue;
            if (!c.is_finite() || c.has_negative()) {
                ++*dropped;
                continue;
            }
            (s >= 2 ? l_joined : l_own) += c;
        }
    }
    // VM at every non-specular surface vertex.
    for (int t = 2; techniques_.vm && t <= n_camera; ++t) {
        if (cv[t - 1].type != VertexType::Surface || !sc.cmis[std::size_t(t - 1)].nonspecular) continue;
        SampledSpectrum term;
        l_own += merge(ctx, sc, t, &term, merges, dropped);
        l_merged_terminated += term;
    }

    // The sample's value, its parts each at the wavelength densities it was found with; the film's
    // maxcomponentvalue limits the whole sample, as Sensor::to_film limits one (pbrt-v4's RGBFilm).
    const Sensor& sensor = scene_.sensor;
    Color3 value = sensor.to_rgb(Radiance3(l_own), tc.lambda);
    Color3 sensor_value = sensor.limited() ? sensor.sensor_xyz(Radiance3(l_own), tc.lambda) : Color3(0.0f);
    auto add_part = [&](const SampledSpectrum& part, const SampledWavelengths& lambda) {
        value += sensor.to_rgb(Radiance3(part), lambda);
        if (sensor.limited()) sensor_value += sensor.sensor_xyz(Radiance3(part), lambda);
    };
    if (!l_joined.is_black()) {
        SampledWavelengths lambda = tc.lambda;
        if (light_terminated) lambda.terminate_secondary();
        add_part(l_joined, lambda);
    }
    if (!l_merged_terminated.is_black()) {
        SampledWavelengths lambda = tc.lambda;
        lambda.terminate_secondary();
        add_part(l_merged_terminated, lambda);
    }
    if (sensor.limited()) value *= sensor.limit_scale(sensor_value);
    if (!value.is_finite()) {
        ++*dropped;
        value = Color3(0.0f);
    }
    film_.add_sample(x, y, value, fs.weight);
}

void VcmRender::camera_pass(int sample_index, tbb::task_arena& arena) {
    const std::size_t chunks = (pixels_ + kChunk - 1) / kChunk;
    merges_per_chunk_.assign(chunks, 0);
    dropped_per_chunk_.assign(chunks, 0);
    // Each pixel is written by the one task of its chunk: the film needs no synchronisation.
    arena.execute([&] {
        tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
            ThreadContext& tc = contexts_->local();
            Scratch& sc = scratch_->local();
            const std::size_t p1 = std::min(pixels_, (c + 1) * kChunk);
            for (std::size_t p = c * kChunk; p < p1; ++p)
                trace_camera(int(p % std::size_t(w_)), int(p / std::size_t(w_)), sample_index, tc, sc,
                             &merges_per_chunk_[c], &dropped_per_chunk_[c]);
            tc.arena.reset();
        });
    });
    for (std::size_t c = 0; c < chunks; ++c) {
        merges_ += merges_per_chunk_[c];
        dropped_ += std::uint64_t(dropped_per_chunk_[c]);
    }
}

RenderResult VcmRender::run(VcmStats* stats) {
    const int threads = render_threads(options_);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    RenderArena arena(threads);
    Sampler prototype(render_sampler_kind(options_), options_.spp > 0 ? options_.spp : 1, options_.seed);
    contexts_ = std::make_unique<tbb::enumerable_thread_specific<ThreadContext>>(
        [&] { return ThreadContext(prototype); });
    const int max_depth = max_depth_;
    scratch_ = std::make_unique<tbb::enumerable_thread_specific<Scratch>>(
        [max_depth] { return Scratch(max_depth); });
    const SampleShare share = sample_share(options_.group);
    // The iterations' wavelengths: the base-3 radical inverse of the iteration, shifted by the seed's hash.
    const double u_shift = double(hash(options_.seed, std::uint64_t(0x56434d)) >> 11) * 0x1p-53;
    const bool timed = options_.time_budget > 0;
    Progress progress("render", timed ? 0 : pixels_ * std::uint64_t(share.count(options_.spp)), "samples",
                      options_.quiet);
    std::size_t vertex_bytes = 0;
    std::uint64_t stored = 0;
    const int passes = run_passes(
        options_, progress,
        [&](int k0, int k1) {
            for (int k = k0; k < k1; ++k) {
                const int index = share.index(k);
                // Paper §5.1: r_i = r_1 i^((α−1)/2), i from 1.
                radius_ = radius0_ * std::pow(float(index + 1), 0.5f * (settings_.alpha - 1));
                techniques_.eta_vcm = float(double(n_light_) * kPi * double(radius_) * radius_);
                if (options_.spectral) {
                    double u = radical_inverse_3(std::uint32_t(index)) + u_shift;
                    lambda_ = SampledWavelengths::sample_visible(
                        float(std::min(u - std::floor(u), 0.99999994)), scene_.color_space);
                } else {
                    lambda_ = SampledWavelengths::rgb_mode();
                }
                light_pass(index, arena);
                build_grid();
                camera_pass(index, arena);
                progress.add(pixels_);
                std::size_t bytes = 0;
                stored = 0;
                for (const LightChunk& c : light_chunks_) {
                    bytes += c.vertices.capacity() * sizeof(StoredVertex) +
                             c.path_begin.capacity() * sizeof(std::uint32_t) +
                             c.splats.capacity() * sizeof(Splat);
                    stored += c.vertices.size();
                }
                vertex_bytes = std::max(vertex_bytes, bytes);
            }
        },
        [&](int k) { return image(k); });
    progress.finish();

    RenderResult r;
    for (auto& tc : *contexts_) r.rays += tc.rays;
    r.nonfinite_samples = dropped_;
    r.spp = sum_over_group(options_, passes, film_.accumulators(), r);
    if (options_.group) options_.group->sum(splat_film_.accumulators(), false);
    r.seconds = progress.elapsed_seconds();
    r.image = image(r.spp);
    r.samples = pixels_ * std::uint64_t(r.spp);
    r.threads = threads;
    if (stats) {
        stats->iterations = passes;
        stats->light_subpaths = std::uint64_t(passes) * n_light_;
        stats->light_vertices = stored;
        stats->merges = sum_counter(options_.group, merges_);
        stats->grid_bytes = grid_bytes_;
        stats->vertex_bytes = vertex_bytes;
        stats->initial_radius = radius0_;
        stats->final_radius = radius_;
    }
    return r;
}

Image VcmRender::image(int passes) const {
    Image img = film_.resolve();
    Image s = splat_film_.resolve(passes);
    for (std::size_t i = 0; i < img.pixel_count(); ++i) img.data()[i] += s.data()[i];
    return img;
}

} // namespace

bool parse_vcm_mode(const std::string& name, VcmSettings::Mode* mode) {
    if (name == "vcm")
        *mode = VcmSettings::Mode::VCM;
    else if (name == "vc")
        *mode = VcmSettings::Mode::VC;
    else if (name == "vm")
        *mode = VcmSettings::Mode::VM;
    else
        return false;
    return true;
}

VCMIntegrator::VCMIntegrator(const Scene& scene, const VcmSettings& settings)
    : WholeImageIntegrator(scene), settings_(settings) {
    if (settings_.max_depth < 0) settings_.max_depth = kUnboundedDepth;
    if (!scene.camera || !scene.camera->has_importance())
        throw Error("integrator \"vcm\" needs a perspective camera or an orthographic one without a lens "
                    "(the realistic camera and a thin-lens orthographic one have no importance function)");
}

float VCMIntegrator::initial_radius() const {
    if (settings_.radius > 0) return settings_.radius;
    Point3f c;
    float r = 0;
    scene_.accelerator.bounds().bounding_sphere(&c, &r);
    // Half the footprint of a pixel on the scene's bounding sphere's diameter spread over the image's larger
    // side (about a pixel's footprint where the scene fills the view).
    return r / float(std::max(1, std::max(scene_.width, scene_.height)));
}

long long VCMIntegrator::light_subpaths_per_iteration() const {
    return settings_.photons_per_iteration > 0 ? settings_.photons_per_iteration
                                               : (long long)scene_.width * (long long)scene_.height;
}

RenderResult VCMIntegrator::render_vcm(const RenderOptions& options, VcmStats* stats) const {
    if (options.spp <= 0 && options.time_budget <= 0)
        throw Error("the number of iterations must be positive");
    const float r0 = initial_radius();
    if (!(r0 > 0) || !std::isfinite(r0)) throw Error("vcm's merging radius must be positive");
    if (!(settings_.alpha > 0 && settings_.alpha <= 1)) throw Error("vcm's alpha must be in (0, 1]");
    VcmRender r(scene_, settings_, settings_.max_depth, light_subpaths_per_iteration(), r0, options);
    return r.run(stats);
}

RenderResult VCMIntegrator::render_image(const RenderOptions& options) const {
    VcmStats st;
    RenderResult r = render_vcm(options, &st);
    if (!options.quiet)
        fmt::print(stderr,
                   "vcm: {} iterations of {} light subpaths; radius {:.3g} -> {:.3g}; {:.3g} merges; memory: "
                   "light vertices {:.1f} MB ({} stored), grid {:.1f} MB\n",
                   st.iterations, light_subpaths_per_iteration(), st.initial_radius, st.final_radius,
                   double(st.merges), st.vertex_bytes / 1e6, st.light_vertices, st.grid_bytes / 1e6);
    return r;
}

} // namespace illum
