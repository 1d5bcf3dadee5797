#include "illum/render/sppm_integrator.h"

#include "illum/render/texture_footprint.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fmt/core.h>
#include <memory>
#include <new>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <thread>
#include <vector>

#include "illum/light/light.h"
#include "illum/math/rng.h"
#include "illum/render/photon_tracer.h"
#include "illum/render/render_arena.h"
#include "illum/render/visible_point_grid.h"
#include "illum/util/error.h"
#include "illum/util/progress.h"

namespace illum {

namespace {

constexpr float kGamma = 2.0f / 3.0f; // Hachisuka & Jensen's α: the fraction of new photons kept
constexpr int kTileSize = 16;
constexpr std::size_t kChunkBudgetBytes = std::size_t(256) << 20; // the per-chunk Φ/M arrays at most
constexpr int kMaxChunks = 16;

// The radical inverse of i in base 3 (pbrt-v4 picks an SPPM iteration's wavelengths with it).
float radical_inverse_3(std::uint32_t i) {
    double inv = 1.0 / 3, f = inv, v = 0;
    for (; i > 0; i /= 3, f *= inv) v += f * double(i % 3);
    return float(std::min(v, 0.99999994));
}

struct VisiblePoint {
    Point3f p;
    Vector3f wo;
    BSDF bsdf; // null: no visible point this iteration
    SampledSpectrum beta;
    bool secondary_terminated = false;
};

// Arena blocks that outlive a camera pass: the visible points' BSDFs of one tile must stay valid through
// the photon pass. Blocks are kept between iterations (reset, not freed), so after the first iteration
// nothing is allocated.
class TileBsdfStore {
public:
    void reset() {
        for (auto& b : blocks_) b->reset();
        current_ = 0;
    }
    BSDF make(const Material& m, const SurfaceHit& hit, SampledWavelengths& lambda) {
        for (;;) {
            if (current_ == blocks_.size()) blocks_.push_back(std::make_unique<ScratchArena>(kBlockBytes));
            try {
                return m.bsdf(hit, lambda, *blocks_[current_]);
            } catch (const std::bad_alloc&) {
                if (blocks_[current_]->used() == 0) throw; // a BSDF larger than a block
                ++current_;
            }
        }
    }
    std::size_t capacity_bytes() const { return blocks_.size() * kBlockBytes; }

private:
    static constexpr std::size_t kBlockBytes = 16 * 1024;
    std::vector<std::unique_ptr<ScratchArena>> blocks_;
    std::size_t current_ = 0;
};

struct Tile {
    int x0, y0, x1, y1;
};

// Per-thread state of the camera pass.
struct CameraThread {
    Sampler sampler;
    ScratchArena arena;
    std::uint64_t rays = 0;
    explicit CameraThread(const Sampler& s) : sampler(s) {}
};

// Per-thread state of the photon pass.
struct PhotonThread {
    Sampler sampler;
    ScratchArena arena;
    std::uint64_t rays = 0, gathers = 0;
    explicit PhotonThread(const Sampler& s) : sampler(s) {}
};

// One render: the per-pixel state (visible points, R, N, τ, L_d), the per-chunk gathers and the grid, kept
// across the iterations.
class SppmRender {
public:
    SppmRender(const Scene& scene, const SppmSettings& s, long long photons, const RenderOptions& o)
        : scene_(scene), settings_(s), options_(o), photons_(std::uint64_t(photons)),
          tracer_(scene, s.max_depth) {}
    RenderResult run(SppmStats* stats);

private:
    bool unoccluded(const SurfaceHit& hit, const LightLiSample& ls, std::uint64_t& rays) const;
    void camera_pass(int iteration, const SampledWavelengths& pass_lambda);
    void trace_camera_path(int x, int y, int iteration, const SampledWavelengths& pass_lambda,
                           CameraThread& t, TileBsdfStore& store);
    SampledSpectrum sample_direct(const SurfaceHit& hit, const BSDF& bsdf, const SampledWavelengths& lambda,
                                  CameraThread& t) const;
    void photon_pass(int iteration, const SampledWavelengths& pass_lambda);
    void update_pixels(tbb::task_arena& arena);
    Image image(int iterations) const;

    const Scene& scene_;
    SppmSettings settings_;
    RenderOptions options_;
    std::uint64_t photons_;
    PhotonTracer tracer_;
    bool spectral_ = false;
    int w_ = 0, h_ = 0;
    std::size_t pixels_ = 0;
    std::vector<Tile> tiles_;
    std::vector<TileBsdfStore> stores_;
    std::unique_ptr<tbb::enumerable_thread_specific<CameraThread>> camera_threads_;
    std::unique_ptr<tbb::enumerable_thread_specific<PhotonThread>> photon_threads_;

    // Per pixel.
    std::vector<VisiblePoint> vp_;
    std::vector<Point3f> vp_p_;
    std::vector<float> radius_, vp_radius_, n_;
    std::vector<Color3> tau_, ld_;
    std::atomic<std::uint64_t> nonfinite_{0};

    // Per chunk × pixel.
    int chunks_ = 1;
    std::vector<Color3> chunk_phi_;
    std::vector<std::uint32_t> chunk_m_;
    // In a render group (render_group.h), each pixel's Φ (rgb) and M of this iteration, summed over the
    // ranks, which each trace their own slice of the iteration's photons.
    std::vector<double> group_gathered_;

    VisiblePointGrid grid_;
    std::unique_ptr<FilmResponse> response_, response_terminated_;
    SppmStats stats_;
};

bool SppmRender::unoccluded(const SurfaceHit& hit, const LightLiSample& ls, std::uint64_t& rays) const {
    ++rays;
    Ray shadow = ls.at_infinity
                     ? hit.spawn_ray(ls.wi)
                     : (ls.n_light == Normal3f{} ? hit.spawn_ray_to(ls.p_light)
                                                 : spawn_ray_to(hit.p, hit.p_error, hit.n, ls.p_light,
                                                                ls.p_light_error, ls.n_light));
    shadow.time = hit.time;
    return !scene_.occluded(shadow);
}

// Next-event estimation at a camera vertex: one light picked by the light sampler for the point, weighed
// against BSDF sampling by the power heuristic (PBR 4th ed. §13.4; pbrt-v4's SPPMIntegrator::SampleLd).
SampledSpectrum SppmRender::sample_direct(const SurfaceHit& hit, const BSDF& bsdf,
                                          const SampledWavelengths& lambda, CameraThread& t) const {
    float u_light = t.sampler.get_1d();
    Point2f u_li = t.sampler.get_2d();
    if (!bsdf.is_non_specular()) return {};
    float pmf = 0;
    LightSampleContext ctx(hit);
    const Light* light = scene_.direct_light_sampler.sample(ctx, u_light, &pmf);
    if (!light || !(pmf > 0)) return {};
    auto ls = light->sample_li(ctx, u_li, lambda);
    if (!ls) return {};
    Bsdf3 f = bsdf.f(hit.wo, ls->wi);
    float cos_i = abs_dot(ls->wi, hit.ns);
    if (f.is_black() || !(cos_i > 0) || !unoccluded(hit, *ls, t.rays)) return {};
    Radiance3 l = reflected(f, ls->biradiance, cos_i);
    if (is_delta(light->type())) return l.s / pmf;
    return l.s * (power_heuristic(pmf * ls->pdf, bsdf.pdf(hit.wo, ls->wi)) / pmf);
}

void SppmRender::trace_camera_path(int x, int y, int iteration, const SampledWavelengths& pass_lambda,
                                   CameraThread& t, TileBsdfStore& store) {
    const std::size_t pi = std::size_t(y) * std::size_t(w_) + std::size_t(x);
    VisiblePoint& vp = vp_[pi];
    vp = VisiblePoint{};
    Sampler& sampler = t.sampler;
    sampler.start_pixel_sample({x, y}, iteration);
    // As pbrt-v4's SPPM: the pixel filter only jitters the sample; every pixel takes one sample per
    // iteration, so its weight is constant and dropped.
    FilterSample fs = scene_.pixel_filter_sample(sampler.get_pixel_2d());
    Point2f p_film{float(x) + 0.5f + fs.offset.x, float(y) + 0.5f + fs.offset.y};
    Point2f u_lens = sampler.get_2d_if(scene_.camera->uses_lens_sample());
    SampledWavelengths lambda = pass_lambda;
    if (spectral_ && scene_.camera->is_dispersive()) lambda.terminate_secondary();
    std::optional<CameraRay> cr =
        scene_.camera->generate_ray(p_film, u_lens, spectral_ ? lambda.hero() : kDLineNm);
    if (!cr || cr->weight == 0) return;

    // Film RGB of the path's direct radiance, converted with the wavelengths as they stand when each term
    // is found (a dispersive event changes their densities).
    Color3 ld;
    auto add = [&](const SampledSpectrum& l) {
        if (l.is_black()) return;
        Color3 c = scene_.sensor.to_rgb(Radiance3(l), lambda);
        if (!c.is_finite()) {
            ++nonfinite_;
            return;
        }
        ld += c;
    };

    Ray ray = cr->ray;
    if (scene_.has_motion) ray = scene_.camera_ray_at(ray, scene_.sample_time(sampler.get_1d()));
    SampledSpectrum beta(cr->weight);
    float eta_scale = 1;
    bool specular_bounce = true; // the camera ray counts as specular: its emission is taken in full
    SolidAnglePdf bsdf_pdf;
    LightSampleContext prev_ctx;
    bool have_vp = false;
    const int max_depth = settings_.max_depth;
    for (int depth = 0;;) {
        SurfaceHit hit;
        ++t.rays;
        if (!scene_.intersect(ray, &hit)) {
            for (const Light* env : scene_.infinite_lights) {
                Radiance3 le = env->le(ray, lambda);
                if (le.is_black()) continue;
                float w = specular_bounce
                              ? 1.0f
                              : power_heuristic(bsdf_pdf, scene_.direct_light_sampler.pmf(prev_ctx, env) *
                                                              env->pdf_li(prev_ctx, ray.d, nullptr));
                add(beta * le.s * w);
            }
            break;
        }
        if (hit.area_light) {
            Radiance3 le = hit.area_light->radiance(hit, hit.wo, lambda);
            if (!le.is_black()) {
                float w = specular_bounce
                              ? 1.0f
                              : power_heuristic(bsdf_pdf,
                                                scene_.direct_light_sampler.pmf(prev_ctx, hit.area_light) *
                                                    hit.area_light->pdf_li(prev_ctx, ray.d, &hit));
                add(beta * le.s * w);
            }
        }
        t.arena.reset();
        footprint_from_camera(hit, scene_, 1); // one camera ray per pixel and iteration
        BSDF bsdf = surface_bsdf(hit, lambda, t.arena);
        if (!bsdf) {
            ray = hit.spawn_ray(ray.d); // a pure interface
            continue;
        }
        if (bsdf.flags() == kNone) break;
        // pbrt-v4: the path ends at the maximum depth or one vertex after the visible point (that vertex
        // only supplied the BSDF-sampled half of the visible point's direct light).
        if (depth++ == max_depth || have_vp) break;

        add(beta * sample_direct(hit, bsdf, lambda, t));

        // A diffuse vertex, or a glossy one at the last depth, is the visible point.
        const std::uint8_t flags = bsdf.flags();
        if (has_flag(flags, kDiffuse) || (has_flag(flags, kGlossy) && depth == max_depth)) {
            // The BSDF again, in storage that lasts through the photon pass.
            SampledWavelengths l2 = lambda;
            vp = VisiblePoint{hit.p, hit.wo, store.make(*hit.material, hit, l2), beta,
                              lambda.secondary_terminated()};
            have_vp = true;
        }

        float u_lobe = sampler.get_1d_if(bsdf.reads_lobe_sample());
        Point2f u_dir = sampler.get_2d();
        auto bs = bsdf.sample(hit.wo, u_lobe, u_dir);
        if (!bs) break;
        specular_bounce = bs->is_specular();
        if (bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
        beta *= throughput_weight(bs->f, abs_dot(bs->wi, hit.ns), bs->pdf);
        bsdf_pdf = bs->pdf_is_proportional ? bsdf.pdf(hit.wo, bs->wi) : bs->pdf;
        if (!beta.is_finite() || beta.is_black()) break;
        // Russian roulette as pbrt-v4's SPPM: continue with probability max(0.05, ...) below throughput 1.
        float rr = beta.max_component() * eta_scale;
        if (rr < 1) {
            float q = std::max(0.05f, 1 - rr);
            if (sampler.get_1d() < q) break;
            beta /= 1 - q;
        }
        prev_ctx = LightSampleContext(hit);
        ray = hit.spawn_ray(bs->wi);
    }
    t.arena.reset();
    ld_[pi] += ld;
    if (vp.bsdf && !vp.beta.is_finite()) {
        ++nonfinite_;
        vp.bsdf = BSDF();
    }
}

void SppmRender::camera_pass(int iteration, const SampledWavelengths& pass_lambda) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles_.size(), 1), [&](const auto& range) {
        CameraThread& t = camera_threads_->local();
        for (std::size_t ti = range.begin(); ti != range.end(); ++ti) {
            const Tile& tile = tiles_[ti];
            stores_[ti].reset();
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x)
                    trace_camera_path(x, y, iteration, pass_lambda, t, stores_[ti]);
        }
    });
    for (std::size_t i = 0; i < pixels_; ++i) {
        vp_p_[i] = vp_[i].p;
        vp_radius_[i] = vp_[i].bsdf ? radius_[i] : 0.0f;
    }
}

void SppmRender::photon_pass(int iteration, const SampledWavelengths& pass_lambda) {
    std::fill(chunk_phi_.begin(), chunk_phi_.end(), Color3());
    std::fill(chunk_m_.begin(), chunk_m_.end(), 0u);
    // This process's photons of the iteration: all of them, or its rank's slice [lo, hi) in a group.
    const RenderGroup* group = options_.group;
    const std::uint64_t n = group ? std::uint64_t(group->size()) : 1,
                        r = group ? std::uint64_t(group->rank()) : 0;
    const std::uint64_t lo = photons_ * r / n, count = photons_ * (r + 1) / n - lo;
    const std::uint64_t first = std::uint64_t(iteration) * photons_ + lo;
    tbb::parallel_for(tbb::blocked_range<int>(0, chunks_, 1), [&](const auto& range) {
        PhotonThread& t = photon_threads_->local();
        for (int c = range.begin(); c != range.end(); ++c) {
            Color3* phi = chunk_phi_.data() + std::size_t(c) * pixels_;
            std::uint32_t* m = chunk_m_.data() + std::size_t(c) * pixels_;
            const std::uint64_t i0 = count * std::uint64_t(c) / std::uint64_t(chunks_),
                                i1 = count * std::uint64_t(c + 1) / std::uint64_t(chunks_);
            for (std::uint64_t i = i0; i < i1; ++i) {
                t.rays +=
                    tracer_.trace(first + i, pass_lambda, t.sampler, t.arena, [&](const PhotonArrival& a) {
                        if (a.bounce == 0) return; // direct light: L_d has it
                        grid_.for_candidates(a.hit.p, [&](std::uint32_t v) {
                            const VisiblePoint& vp = vp_[v];
                            Vector3f d = vp.p - a.hit.p;
                            if (dot(d, d) > vp_radius_[v] * vp_radius_[v]) return;
                            // Φ_i += β_cam f(x, ω_o, ω_photon) β_photon, in film RGB.
                            SampledSpectrum gathered = vp.beta * vp.bsdf.f(vp.wo, a.wi).s * a.beta;
                            bool terminated = vp.secondary_terminated || a.lambda.secondary_terminated();
                            Color3 c_phi =
                                terminated ? response_terminated_->rgb(gathered) : response_->rgb(gathered);
                            if (c_phi.is_finite()) phi[v] += c_phi;
                            ++m[v];
                            ++t.gathers;
                        });
                    });
            }
        }
    });
}

// Hachisuka & Jensen 2009, eqs. 7-8: N̂ = N + αM, R̂ = R √(N̂ / (N + M)), τ̂ = (τ + Φ) (R̂ / R)².
// In a group every rank sums its chunks, the sums are added over the ranks (the same bits everywhere), and
// every rank updates its pixels alike.
void SppmRender::update_pixels(tbb::task_arena& arena) {
    RenderGroup* group = options_.group;
    auto chunk_sum = [&](std::size_t i, Color3& phi, std::uint64_t& m) {
        for (int c = 0; c < chunks_; ++c) { // in chunk order: the same sum at any thread count
            phi += chunk_phi_[std::size_t(c) * pixels_ + i];
            m += chunk_m_[std::size_t(c) * pixels_ + i];
        }
    };
    if (group) {
        group_gathered_.resize(pixels_ * 4);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels_, 4096), [&](const auto& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    Color3 phi;
                    std::uint64_t m = 0;
                    chunk_sum(i, phi, m);
                    double* g = &group_gathered_[i * 4];
                    g[0] = phi[0], g[1] = phi[1], g[2] = phi[2], g[3] = double(m);
                }
            });
        });
        group->sum(group_gathered_, true);
    }
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels_, 4096), [&](const auto& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                Color3 phi;
                std::uint64_t m = 0;
                if (group) {
                    const double* g = &group_gathered_[i * 4];
                    phi = Color3(float(g[0]), float(g[1]), float(g[2]));
                    m = std::uint64_t(g[3]);
                } else {
                    chunk_sum(i, phi, m);
                }
                if (m == 0) continue;
                float n_new = n_[i] + kGamma * float(m);
                float r_new = radius_[i] * std::sqrt(n_new / (n_[i] + float(m)));
                tau_[i] = (tau_[i] + phi) * ((r_new * r_new) / (radius_[i] * radius_[i]));
                n_[i] = n_new;
                radius_[i] = r_new;
            }
        });
    });
}

// L = L_d / k + τ / (k N π R²).
Image SppmRender::image(int k) const {
    Image img(w_, h_);
    const double photons = double(k) * double(photons_);
    for (std::size_t i = 0; i < pixels_; ++i) {
        Color3 l = ld_[i] / float(k);
        if (photons > 0)
            l += tau_[i] * float(1.0 / (photons * kPiD * double(radius_[i]) * double(radius_[i])));
        img.data()[i] = l;
    }
    return img;
}

RenderResult SppmRender::run(SppmStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    w_ = scene_.width;
    h_ = scene_.height;
    pixels_ = std::size_t(w_) * std::size_t(h_);
    if (pixels_ == 0) throw Error("the film has no pixels");
    spectral_ = options_.spectral;
    int threads = render_threads(options_);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    RenderArena arena(threads);

    for (int y = 0; y < h_; y += kTileSize)
        for (int x = 0; x < w_; x += kTileSize)
            tiles_.push_back({x, y, std::min(x + kTileSize, w_), std::min(y + kTileSize, h_)});
    stores_.resize(tiles_.size());
    vp_.assign(pixels_, VisiblePoint{});
    vp_p_.assign(pixels_, Point3f{});
    vp_radius_.assign(pixels_, 0.0f);
    radius_.assign(pixels_, settings_.initial_radius);
    n_.assign(pixels_, 0.0f);
    tau_.assign(pixels_, Color3());
    ld_.assign(pixels_, Color3());
    // Chunks: as many as fit the budget, up to kMaxChunks; they depend on the image size only.
    const std::size_t per_chunk = pixels_ * (sizeof(Color3) + sizeof(std::uint32_t));
    chunks_ = int(std::clamp<std::size_t>(kChunkBudgetBytes / per_chunk, 1, kMaxChunks));
    chunk_phi_.assign(std::size_t(chunks_) * pixels_, Color3());
    chunk_m_.assign(std::size_t(chunks_) * pixels_, 0u);

    const int iterations_asked = options_.spp > 0 ? options_.spp : 1;
    const Sampler camera_prototype = make_sampler(options_, iterations_asked, {scene_.width, scene_.height});
    Sampler photon_prototype(SamplerKind::sobol, 1, hash(options_.seed, settings_.seed));
    camera_threads_ = std::make_unique<tbb::enumerable_thread_specific<CameraThread>>(
        [&] { return CameraThread(camera_prototype); });
    photon_threads_ = std::make_unique<tbb::enumerable_thread_specific<PhotonThread>>(
        [&] { return PhotonThread(photon_prototype); });

    const bool timed = options_.time_budget > 0;
    Progress progress("sppm", timed ? 0 : std::uint64_t(iterations_asked), "iterations", options_.quiet);
    int k = 0;
    double photon_seconds = 0;
    for (;; ++k) {
        if (timed && k > 0) {
            bool more = progress.elapsed_seconds() < options_.time_budget;
            if (options_.group) more = options_.group->broadcast(more); // rank 0's clock decides
            if (!more) break;
        } else if (!timed && k >= iterations_asked) {
            break;
        }
        SampledWavelengths lambda =
            spectral_ ? SampledWavelengths::sample_visible(
                            scene_.wavelength_sample(radical_inverse_3(std::uint32_t(k))), scene_.color_space)
                      : SampledWavelengths::rgb_mode();
        response_ = std::make_unique<FilmResponse>(scene_.sensor, lambda);
        SampledWavelengths terminated = lambda;
        terminated.terminate_secondary();
        response_terminated_ = std::make_unique<FilmResponse>(scene_.sensor, terminated);

        arena.execute([&] { camera_pass(k, lambda); });
        grid_.build(vp_p_, vp_radius_);
        if (grid_.memory_bytes() > stats_.grid_bytes) {
            stats_.grid_bytes = grid_.memory_bytes();
            stats_.grid_entries = grid_.entry_count();
        }
        auto t0 = std::chrono::steady_clock::now();
        arena.execute([&] { photon_pass(k, lambda); });
        photon_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        update_pixels(arena);
        progress.add(1);
        const double fraction =
            timed ? progress.elapsed_seconds() / options_.time_budget : double(k + 1) / iterations_asked;
        if (timed) progress.set_fraction(fraction);
        if (options_.preview)
            options_.preview->frame(image(k + 1), k + 1, timed ? 0 : iterations_asked,
                                    std::min(1.0, fraction));
    }
    progress.finish();

    RenderResult r;
    r.image = image(k);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.spp = k;
    r.samples = pixels_ * std::uint64_t(k);
    std::uint64_t photon_rays = 0;
    for (auto& t : *photon_threads_) {
        photon_rays += t.rays;
        stats_.photon_gathers += t.gathers;
    }
    // In a group every rank traces the same camera paths and its own photons.
    for (auto& t : *camera_threads_) r.rays += t.rays;
    r.rays += sum_counter(options_.group, photon_rays);
    stats_.photon_gathers = sum_counter(options_.group, stats_.photon_gathers);
    r.nonfinite_samples = nonfinite_;
    r.threads = threads;
    if (stats) {
        stats_.iterations = k;
        stats_.photons = std::uint64_t(k) * photons_;
        stats_.pixel_bytes =
            pixels_ * (sizeof(VisiblePoint) + sizeof(Point3f) + 3 * sizeof(float) + 2 * sizeof(Color3));
        stats_.chunk_bytes = chunk_phi_.size() * sizeof(Color3) + chunk_m_.size() * sizeof(std::uint32_t);
        for (const auto& s : stores_) stats_.bsdf_bytes += s.capacity_bytes();
        stats_.photon_seconds = photon_seconds;
        auto [lo, hi] = std::minmax_element(radius_.begin(), radius_.end());
        stats_.final_radius_min = *lo;
        stats_.final_radius_max = *hi;
        *stats = stats_;
    }
    return r;
}

} // namespace

long long SPPMIntegrator::photons_per_iteration() const {
    return settings_.photons_per_iteration > 0 ? settings_.photons_per_iteration
                                               : (long long)scene_.width * (long long)scene_.height;
}

RenderResult SPPMIntegrator::render_sppm(const RenderOptions& options, SppmStats* stats) const {
    if (options.spp <= 0 && options.time_budget <= 0)
        throw Error("the number of iterations must be positive");
    if (settings_.max_depth < 0) throw Error("sppm needs a finite maxdepth");
    if (!(settings_.initial_radius > 0)) throw Error("sppm's radius must be positive");
    SppmRender r(scene_, settings_, photons_per_iteration(), options);
    return r.run(stats);
}

RenderResult SPPMIntegrator::render_image(const RenderOptions& options) const {
    SppmStats st;
    RenderResult r = render_sppm(options, &st);
    if (!options.quiet)
        fmt::print(
            stderr,
            "sppm: {} iterations of {} photons, {:.3g} photons/s in the photon passes ({:.2f} s); radius "
            "{:.3g}-{:.3g}; memory: grid {:.1f} MB, per-chunk gathers {:.1f} MB, pixels {:.1f} MB, BSDFs "
            "{:.1f} MB\n",
            st.iterations, photons_per_iteration(),
            st.photon_seconds > 0 ? st.photons / st.photon_seconds : 0.0, st.photon_seconds,
            st.final_radius_min, st.final_radius_max, st.grid_bytes / 1e6, st.chunk_bytes / 1e6,
            st.pixel_bytes / 1e6, st.bsdf_bytes / 1e6);
    return r;
}

} // namespace illum
