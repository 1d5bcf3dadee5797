#include "illum/geometry/create_shape.h"

#include <algorithm>
#include <fmt/format.h>

#include "illum/geometry/cylinder.h"
#include "illum/geometry/disk.h"
#include "illum/geometry/displace_mesh.h"
#include "illum/geometry/loop_subdivision.h"
#include "illum/geometry/ply.h"
#include "illum/geometry/sphere.h"
#include "illum/image/image_io.h"

namespace illum {

namespace {

// Where a shape's parameter was written (the shape's own position when it was not).
SourceLocation param_loc(const ShapeDesc& s, const char* name) {
    const Param* p = s.params.find(name);
    return p ? p->loc : s.loc;
}

// pbrt-v4's "phimax" in degrees, (0, 360], as radians.
float phimax_of(const ShapeDesc& s) {
    float phimax = s.params.get_float("phimax", 360);
    if (!(phimax > 0 && phimax <= 360))
        throw Error(param_loc(s, "phimax"),
                    fmt::format("{} phimax must be in (0, 360], not {}", s.type, phimax));
    return phimax * (kPi / 180);
}

// Outward normals flip under ReverseOrientation and under a transform that swaps handedness (pbrt-v4).
bool flip_of(const ShapeDesc& s) { return s.reverse_orientation != s.world_from_object.swaps_handedness(); }

// The positions "P" and the "indices" of a mesh given inline, `per` vertices per face, checked against each
// other; without indices the mesh must be exactly one face.
std::vector<int> positions_and_indices(const ShapeDesc& s, TriangleMesh& mesh, int per) {
    mesh.p = s.params.get_point3s("P");
    if (mesh.p.empty()) throw Error(s.loc, fmt::format("{} needs \"point3 P\"", s.type));
    std::vector<int> idx = s.params.get_ints("indices");
    if (idx.empty()) {
        if (mesh.p.size() != std::size_t(per))
            throw Error(s.loc, fmt::format("{} without \"indices\" must have {} vertices", s.type, per));
        for (int i = 0; i < per; ++i) idx.push_back(i);
        return idx;
    }
    if (idx.size() % per != 0)
        throw Error(s.params.find("indices")->loc,
                    fmt::format("{} has {} indices, not a multiple of {}", s.type, idx.size(), per));
    for (int i : idx)
        if (i < 0 || std::size_t(i) >= mesh.p.size())
            throw Error(s.params.find("indices")->loc,
                        fmt::format("{} index {} is out of range (the mesh has {} vertices)", s.type, i,
                                    mesh.p.size()));
    return idx;
}

// Per-vertex normals and uv of a mesh given inline.
void vertex_data(const ShapeDesc& s, TriangleMesh& mesh) {
    mesh.n = s.params.get_normals("N");
    if (!mesh.n.empty() && mesh.n.size() != mesh.p.size())
        throw Error(s.params.find("N")->loc, fmt::format("{} has a different number of N and P", s.type));
    mesh.uv = s.params.get_point2s("uv");
    if (mesh.uv.empty() && s.type == "trianglemesh") mesh.uv = s.params.get_point2s("st");
    if (!mesh.uv.empty() && mesh.uv.size() != mesh.p.size())
        throw Error(s.loc, fmt::format("{} has a different number of uv and P", s.type));
}

// pbrt-v4's "faceIndices" (the face a Ptex texture reads): one per triangle or patch, or none.
std::vector<int> face_indices(const ShapeDesc& s, std::size_t faces) {
    std::vector<int> fi = s.params.get_ints("faceIndices");
    if (!fi.empty() && fi.size() != faces)
        throw Error(s.params.find("faceIndices")->loc,
                    fmt::format("{} has {} \"faceIndices\" for {} faces", s.type, fi.size(), faces));
    return fi;
}

std::unique_ptr<TriangleMesh> triangle_mesh(const ShapeDesc& s) {
    auto mesh = std::make_unique<TriangleMesh>();
    std::vector<int> idx = positions_and_indices(s, *mesh, 3);
    mesh->indices.assign(idx.begin(), idx.end());
    vertex_data(s, *mesh);
    mesh->face_indices = face_indices(s, idx.size() / 3);
    return mesh;
}

// pbrt-v4's "emissionfilename" of a bilinearmesh: the density its patches sample emitting points by, in
// proportion to the image's pixels' channel average (pbrt-v4's Image::GetSamplingDistribution), the image
// flipped so that v = 0 is its bottom row (an area light's image is read at (u, 1 - v)). pbrt-v4 ignores it,
// with an error message, when the mesh has "uv"; so does illum, with a warning.
std::shared_ptr<const Distribution2D> emission_distribution(const ShapeDesc& s, bool has_uv,
                                                            Diagnostics& diag) {
    const Param* p = s.params.find("emissionfilename");
    std::string file = s.params.get_string("emissionfilename", "");
    if (file.empty()) return nullptr;
    if (has_uv) {
        diag.unsupported(p->loc, "bilinearmesh: \"emissionfilename\" is ignored when \"uv\" is given (as in "
                                 "pbrt-v4)");
        return nullptr;
    }
    Image img;
    try {
        img = read_image(file);
    } catch (const Error& e) {
        diag.missing_file(p->loc, e.what());
        return nullptr;
    }
    const int w = img.width(), h = img.height();
    std::vector<float> weights(std::size_t(w) * std::size_t(h));
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            Color3 c = img(x, h - 1 - row);
            weights[std::size_t(row) * std::size_t(w) + std::size_t(x)] = (c.r + c.g + c.b) / 3;
        }
    return std::make_shared<const Distribution2D>(weights, w, h);
}

// pbrt-v4's bilinearmesh: four indices per patch (p00, p10, p01, p11), per-vertex "N" and "uv", and
// "emissionfilename".
std::unique_ptr<BilinearPatchMesh> bilinear_mesh(const ShapeDesc& s, Diagnostics& diag) {
    TriangleMesh data;
    std::vector<int> idx = positions_and_indices(s, data, 4);
    vertex_data(s, data);
    auto mesh = std::make_unique<BilinearPatchMesh>();
    mesh->p = std::move(data.p);
    mesh->n = std::move(data.n);
    mesh->uv = std::move(data.uv);
    mesh->indices.assign(idx.begin(), idx.end());
    mesh->face_indices = face_indices(s, idx.size() / 4);
    mesh->emission_distribution = emission_distribution(s, !mesh->uv.empty(), diag);
    return mesh;
}

// pbrt-v4's loopsubdiv: "levels" (default 3) of Loop subdivision of the triangles "indices" over "P", pushed
// to the limit surface with its normals (loop_subdivision.h); "scheme" is read and ignored, as pbrt-v4 does.
std::unique_ptr<TriangleMesh> loop_subdivision_mesh(const ShapeDesc& s) {
    int levels = s.params.get_int("levels", 3);
    if (levels < 0 || levels > 12)
        throw Error(param_loc(s, "levels"),
                    fmt::format("loopsubdiv levels must be in [0, 12], not {}", levels));
    s.params.get_string("scheme", "loop");
    if (!s.params.has("indices")) throw Error(s.loc, "loopsubdiv needs \"integer indices\"");
    TriangleMesh given;
    std::vector<int> idx = positions_and_indices(s, given, 3);
    SubdividedMesh sub = loop_subdivide(given.p, idx, levels);
    auto mesh = std::make_unique<TriangleMesh>();
    mesh->p = std::move(sub.p);
    mesh->n = std::move(sub.n);
    mesh->indices = std::move(sub.indices);
    return mesh;
}

// pbrt-v4's plymesh "displacement" (a float texture; a float is taken as a constant one): the mesh refined
// until its edges are shorter than "edgelength" (default 1) times Option "displacementedgescale" in world
// space, then displaced along its normals (displace_mesh.h).
void displace_ply_mesh(const ShapeDesc& s, TriangleMesh& mesh, TextureParams& textures, float edge_scale) {
    float edge = s.params.get_float("edgelength", 1) * edge_scale; // read, as pbrt-v4 does, even unused
    const FloatTexture* d = textures.scalar(s.params, "displacement", std::nullopt);
    if (!d) return;
    SourceLocation loc = param_loc(s, "displacement");
    if (!(edge > 0) || !std::isfinite(edge))
        throw Error(
            param_loc(s, "edgelength"),
            fmt::format("plymesh edgelength times displacementedgescale must be positive, not {}", edge));
    if (mesh.uv.empty()) throw Error(loc, "plymesh \"displacement\" needs the mesh's uv (as in pbrt-v4)");
    try {
        displace_mesh(mesh, *d, s.world_from_object, edge);
    } catch (const Error& e) {
        throw Error(loc, fmt::format("plymesh: {}", e.what()));
    }
}

// pbrt-v4's plymesh: triangles become a triangle mesh and, without displacement, quads bilinear patches
// (pbrt-v4 makes a BilinearPatchMesh of them); with displacement quads are split into two triangles first.
// Fills g.mesh and/or g.patches; false when the file is missing or holds no faces.
bool ply_mesh(const ShapeDesc& s, TextureParams& textures, float edge_scale, ShapeGeometry& g) {
    Diagnostics& diag = textures.diagnostics();
    std::string file = s.params.get_string("filename", "");
    if (file.empty()) throw Error(s.loc, "plymesh needs \"string filename\"");
    bool displaced = s.params.has("displacement");
    TriangleMeshData data;
    try {
        data = read_ply(file, !displaced);
    } catch (const Error& e) {
        diag.missing_file(s.params.find("filename")->loc, e.what());
        return false;
    }
    if (data.indices.empty() && data.quads.empty()) {
        diag.unsupported(s.loc, fmt::format("plymesh \"{}\" has no faces and is skipped", file));
        return false;
    }
    if (!data.quads.empty()) {
        g.patches = std::make_unique<BilinearPatchMesh>();
        g.patches->p = data.positions;
        g.patches->n = data.normals;
        g.patches->uv = data.uvs;
        g.patches->indices.assign(data.quads.begin(), data.quads.end());
        g.patches->face_indices = std::move(data.quad_face_indices);
    }
    if (data.indices.empty()) {              // quads only, so no displacement
        s.params.get_float("edgelength", 1); // read, as pbrt-v4 does, even unused
        return true;
    }
    g.mesh = std::make_unique<TriangleMesh>();
    g.mesh->p = std::move(data.positions);
    g.mesh->n = std::move(data.normals);
    g.mesh->uv = std::move(data.uvs);
    g.mesh->indices.assign(data.indices.begin(), data.indices.end());
    g.mesh->face_indices = std::move(data.face_indices);
    displace_ply_mesh(s, *g.mesh, textures, edge_scale);
    return true;
}

std::unique_ptr<AnalyticShape> sphere(const ShapeDesc& s) {
    float r = s.params.get_float("radius", 1);
    if (!(r > 0)) throw Error(param_loc(s, "radius"), "sphere radius must be positive");
    float zmin = s.params.get_float("zmin", -r), zmax = s.params.get_float("zmax", r);
    // pbrt-v4 orders zmin, zmax and clamps them to [-r, r]; an empty range is an error here.
    float z0 = std::clamp(std::min(zmin, zmax), -r, r), z1 = std::clamp(std::max(zmin, zmax), -r, r);
    if (!(z0 < z1))
        throw Error(param_loc(s, s.params.has("zmin") ? "zmin" : "zmax"),
                    fmt::format("sphere zmin ({}) and zmax ({}) leave nothing of the sphere of radius {}",
                                zmin, zmax, r));
    return std::make_unique<SphereShape>(s.world_from_object, r, zmin, zmax, phimax_of(s), flip_of(s));
}

std::unique_ptr<AnalyticShape> disk(const ShapeDesc& s) {
    float r = s.params.get_float("radius", 1), ri = s.params.get_float("innerradius", 0);
    float h = s.params.get_float("height", 0);
    if (!(r > 0) || !(ri >= 0) || !(ri < r) || !std::isfinite(h))
        throw Error(s.loc, "disk needs 0 <= innerradius < radius and a finite height");
    return std::make_unique<DiskShape>(s.world_from_object, h, r, ri, flip_of(s), phimax_of(s));
}

std::unique_ptr<AnalyticShape> cylinder(const ShapeDesc& s) {
    float r = s.params.get_float("radius", 1), z0 = s.params.get_float("zmin", -1),
          z1 = s.params.get_float("zmax", 1);
    if (!(r > 0)) throw Error(param_loc(s, "radius"), "cylinder radius must be positive");
    if (!(z0 != z1) || !std::isfinite(z0) || !std::isfinite(z1))
        throw Error(param_loc(s, s.params.has("zmin") ? "zmin" : "zmax"),
                    "cylinder needs finite zmin != zmax");
    return std::make_unique<CylinderShape>(s.world_from_object, r, z0, z1, phimax_of(s), flip_of(s));
}

// pbrt-v4's "alpha" of a shape, a float or a float texture; nullptr when the shape is opaque.
const FloatTexture* alpha_of(const ShapeDesc& s, TextureParams& textures) {
    const Param* a = s.params.find("alpha");
    if (!a) return nullptr;
    if (a->type == ParamType::Float && s.params.get_float("alpha", 1) >= 1) return nullptr;
    return textures.scalar(s.params, "alpha", 1.0f);
}

} // namespace

std::optional<ShapeGeometry> create_shape(const ShapeDesc& s, TextureParams& textures,
                                          float displacement_edge_scale) {
    if (!s.world_from_object.matrix().is_finite()) throw Error(s.loc, "shape transform is not finite");
    // A constant alpha of 0 removes the shape (pbrt-v4 does the same); any other alpha below 1 is a
    // cut-out.
    if (const Param* a = s.params.find("alpha"))
        if (a->type == ParamType::Float && s.params.get_float("alpha", 1) <= 0) {
            // Its other parameters go unread, but not unused: the report of unused ones passes them.
            for (const Param& p : s.params.params()) p.used = true;
            return std::nullopt;
        }
    ShapeGeometry g;
    g.alpha = alpha_of(s, textures);
    if (s.type == "trianglemesh") {
        g.mesh = triangle_mesh(s);
    } else if (s.type == "bilinearmesh") {
        g.patches = bilinear_mesh(s, textures.diagnostics());
    } else if (s.type == "plymesh") {
        if (!ply_mesh(s, textures, displacement_edge_scale, g)) return std::nullopt;
    } else if (s.type == "sphere") {
        g.analytic = sphere(s);
    } else if (s.type == "disk") {
        g.analytic = disk(s);
    } else if (s.type == "cylinder") {
        g.analytic = cylinder(s);
    } else if (s.type == "curve") {
        g.curves = create_curves(s, textures.diagnostics());
        return g;
    } else if (s.type == "loopsubdiv") {
        g.mesh = loop_subdivision_mesh(s);
    } else if (s.type == "cone" || s.type == "paraboloid" || s.type == "hyperboloid") {
        textures.diagnostics().unsupported(
            s.loc, fmt::format("shape \"{}\" is not supported yet and is skipped", s.type));
        return std::nullopt;
    } else {
        throw Error(s.loc, fmt::format("unknown shape type \"{}\"", s.type));
    }
    if (g.patches) {
        g.patches->flip_normal = flip_of(s);
        g.patches->transform(s.world_from_object, s.reverse_orientation);
        g.patches->finalize();
    }
    if (g.mesh) {
        g.mesh->flip_normal = flip_of(s);
        g.mesh->transform(s.world_from_object);
        // pbrt-v4's TriangleMesh negates given normals under ReverseOrientation (not under a handedness
        // swap); the geometric normal then turns to their side, so the emitting side flips too.
        if (s.reverse_orientation)
            for (Normal3f& n : g.mesh->n) n = -n;
        g.mesh->finalize();
    } else if (g.analytic) {
        g.analytic->set_alpha(g.alpha);
    }
    return g;
}

} // namespace illum
