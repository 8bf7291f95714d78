#include "geometry/shape_factory.h"

#include "geometry/bilinear_mesh.h"
#include "geometry/cylinder.h"
#include "geometry/disk.h"
#include "geometry/loop_subdivision.h"
#include "geometry/mesh_displacement.h"
#include "geometry/mesh_file.h"
#include "geometry/sphere.h"


namespace caustica {

namespace {

// Per-vertex uv as pbrt-v4 writes it ("point2 uv"), also accepting the flat "float uv" of
// pbrt-v3 files.
std::vector<Vec2f> read_uv(const ParameterDictionary &params) {
    for (const ParsedParameter &p : params.parameters()) {
        if (p.name != "uv") continue;
        if (p.type != "float") break;
        p.looked_up = true;
        if (p.numbers.size() % 2 != 0)
            throw InputError(p.loc, "\"float uv\" needs an even number of values");
        std::vector<Vec2f> uv;
        for (size_t i = 0; i < p.numbers.size(); i += 2)
            uv.push_back({float(p.numbers[i]), float(p.numbers[i + 1])});
        return uv;
    }
    return params.get_point2_array("uv");
}

// pbrt-v4 reports per-vertex arrays of the wrong length and carries on without them.
template <typename T>
void discard_if_mismatched(std::vector<T> &values, size_t vertex_count, const std::string &what,
                           const std::string &name, const ParameterDictionary &params) {
    if (values.empty() || values.size() == vertex_count) return;
    warning(params.location(name), what + ": " + std::to_string(values.size()) + " \"" + name +
                                       "\" values for " + std::to_string(vertex_count) +
                                       " vertices; ignoring them");
    values.clear();
}

std::shared_ptr<ShapeGroup> mesh_group(const std::string &type, MeshData data,
                                       const Transform &render_from_object,
                                       bool reverse_orientation, const SourceLocation &loc,
                                       const std::string &what) {
    auto group = std::make_shared<ShapeGroup>();
    group->type = type;
    group->mesh = std::make_shared<TriangleMesh>(render_from_object, reverse_orientation,
                                                 std::move(data.indices), std::move(data.p),
                                                 std::move(data.n), std::move(data.uv), loc, what);
    if (group->mesh->triangle_count() == 0) {
        warning(loc, what + ": no triangles with nonzero area; shape skipped");
        return nullptr;
    }
    return group;
}

// Exact bilinear patches of validated arrays (four indices per patch).
std::shared_ptr<ShapeGroup> patch_group(const std::string &type, std::vector<int> indices, MeshData data,
                                        const Transform &render_from_object, bool reverse_orientation) {
    auto group = std::make_shared<ShapeGroup>();
    group->type = type;
    group->patches = std::make_shared<BilinearPatchMesh>(render_from_object, reverse_orientation, std::move(indices),
                                                         std::move(data.p), std::move(data.n), std::move(data.uv));
    return group;
}

std::shared_ptr<ShapeGroup> create_triangle_mesh(const Transform &render_from_object,
                                                 bool reverse_orientation,
                                                 const ParameterDictionary &params,
                                                 const SourceLocation &loc) {
    MeshData data;
    data.indices = params.get_int_array("indices");
    data.p = params.get_point3_array("P");
    data.n = params.get_normal_array("N");
    data.uv = read_uv(params);
    if (!params.get_vector3_array("S").empty())
        warning(params.location("S"), "trianglemesh: tangents \"S\" are ignored; shading "
                                      "tangents follow dp/du");
    if (data.p.empty()) throw InputError(loc, "trianglemesh: vertex positions \"P\" not given");
    if (data.indices.empty()) {
        if (data.p.size() != 3)
            throw InputError(loc, "trianglemesh: vertex indices \"indices\" not given");
        data.indices = {0, 1, 2};
    }
    discard_if_mismatched(data.n, data.p.size(), "trianglemesh", "N", params);
    discard_if_mismatched(data.uv, data.p.size(), "trianglemesh", "uv", params);
    return mesh_group("trianglemesh", std::move(data), render_from_object, reverse_orientation,
                      params.location("indices"), "trianglemesh");
}

std::vector<std::shared_ptr<ShapeGroup>> create_ply_mesh(const Transform &render_from_object,
                                                         bool reverse_orientation,
                                                         const ParameterDictionary &params,
                                                         const SourceLocation &loc,
                                                         const FloatTexture *displacement) {
    std::string filename = params.get_one_string("filename", "");
    if (filename.empty()) throw InputError(loc, "plymesh: no \"filename\" given");
    std::string path = params.file_path("filename", filename);
    const float edge_length = params.get_one_float("edgelength", 1);
    MeshData data = read_mesh_file(path, params.location("filename"));
    const std::string what = "plymesh \"" + filename + "\"";
    // Quads are pbrt-v4's bilinear patches: the two triangles they are when affine, and exact
    // patches when curved, beside the file's triangles. Displacement refines triangles, so a
    // displaced file's quads are split first, as pbrt-v4 does.
    std::vector<std::shared_ptr<ShapeGroup>> groups;
    if (!data.quads.empty() && !displacement &&
        !bilinear_patches_are_affine(data.quads, data.p, data.n, data.uv)) {
        validate_bilinear_patches(data.quads, data.p, data.n, data.uv, params.location("filename"));
        std::vector<int> quads = std::move(data.quads);
        data.quads.clear();
        if (data.indices.empty())
            return {patch_group("plymesh", std::move(quads), std::move(data), render_from_object, reverse_orientation)};
        groups.push_back(patch_group("plymesh", std::move(quads), data, render_from_object, reverse_orientation));
    }
    split_quads(&data);
    if (displacement)
        data = displace_mesh(std::move(data), *displacement, edge_length, render_from_object,
                             params.location("displacement"), params.location("edgelength"));
    if (auto mesh = mesh_group("plymesh", std::move(data), render_from_object, reverse_orientation,
                               params.location("filename"), what))
        groups.insert(groups.begin(), std::move(mesh));
    return groups;
}

std::shared_ptr<ShapeGroup> create_loop_subdivision(const Transform &render_from_object,
                                                    bool reverse_orientation,
                                                    const ParameterDictionary &params,
                                                    const SourceLocation &loc) {
    std::vector<int> indices = params.get_int_array("indices");
    std::vector<Vec3f> p = params.get_point3_array("P");
    if (indices.empty()) throw InputError(loc, "loopsubdiv: vertex indices \"indices\" not given");
    if (p.empty()) throw InputError(loc, "loopsubdiv: vertex positions \"P\" not given");
    // pbrt-v4 reads "scheme" and ignores it: Loop is the only one.
    params.get_one_string("scheme", "loop");
    MeshData data = loop_subdivide(std::move(indices), p, params.get_one_int("levels", 3),
                                   params.location("indices"));
    return mesh_group("loopsubdiv", std::move(data), render_from_object, reverse_orientation,
                      params.location("indices"), "loopsubdiv");
}

std::shared_ptr<ShapeGroup> create_bilinear_mesh(const Transform &render_from_object,
                                                 bool reverse_orientation,
                                                 const ParameterDictionary &params,
                                                 const SourceLocation &loc) {
    std::vector<int> indices = params.get_int_array("indices");
    std::vector<Vec3f> p = params.get_point3_array("P");
    std::vector<Vec3f> n = params.get_normal_array("N");
    std::vector<Vec2f> uv = read_uv(params);
    if (p.empty()) throw InputError(loc, "bilinearmesh: vertex positions \"P\" not given");
    if (indices.empty()) {
        if (p.size() != 4)
            throw InputError(loc, "bilinearmesh: vertex indices \"indices\" not given");
        indices = {0, 1, 2, 3};
    }
    discard_if_mismatched(n, p.size(), "bilinearmesh", "N", params);
    discard_if_mismatched(uv, p.size(), "bilinearmesh", "uv", params);
    validate_bilinear_patches(indices, p, n, uv, params.location("indices"));
    if (bilinear_patches_are_affine(indices, p, n, uv))
        return mesh_group("bilinearmesh", triangulate_bilinear_patches(indices, p, n, uv), render_from_object,
                          reverse_orientation, params.location("indices"), "bilinearmesh");
    return patch_group("bilinearmesh", std::move(indices), MeshData{{}, {}, std::move(p), std::move(n), std::move(uv)},
                       render_from_object, reverse_orientation);
}

std::shared_ptr<ShapeGroup> create_sphere(const Transform &render_from_object,
                                          bool reverse_orientation,
                                          const ParameterDictionary &params,
                                          const SourceLocation &loc) {
    float radius = params.get_one_float("radius", 1);
    float z_min = params.get_one_float("zmin", -radius);
    float z_max = params.get_one_float("zmax", radius);
    float phi_max = params.get_one_float("phimax", 360);
    if (!(radius > 0) || !(phi_max > 0) || !(z_max != z_min)) {
        warning(loc, "sphere: no surface (radius, zmin..zmax or phimax is empty); skipped");
        return nullptr;
    }
    auto group = std::make_shared<ShapeGroup>();
    group->type = "sphere";
    group->analytic = std::make_shared<Sphere>(render_from_object, reverse_orientation, radius,
                                               z_min, z_max, phi_max);
    return group;
}

std::shared_ptr<ShapeGroup> create_disk(const Transform &render_from_object,
                                        bool reverse_orientation, const ParameterDictionary &params,
                                        const SourceLocation &loc) {
    float height = params.get_one_float("height", 0);
    float radius = params.get_one_float("radius", 1);
    float inner_radius = params.get_one_float("innerradius", 0);
    float phi_max = params.get_one_float("phimax", 360);
    if (!(radius > 0) || !(inner_radius < radius) || !(phi_max > 0)) {
        warning(loc, "disk: no surface (radius <= innerradius or phimax <= 0); skipped");
        return nullptr;
    }
    auto group = std::make_shared<ShapeGroup>();
    group->type = "disk";
    group->analytic = std::make_shared<Disk>(render_from_object, reverse_orientation, height,
                                             radius, std::max(inner_radius, 0.f), phi_max);
    return group;
}

std::shared_ptr<ShapeGroup> create_cylinder(const Transform &render_from_object,
                                            bool reverse_orientation, const ParameterDictionary &params,
                                            const SourceLocation &loc) {
    float radius = params.get_one_float("radius", 1);
    float z_min = params.get_one_float("zmin", -1);
    float z_max = params.get_one_float("zmax", 1);
    float phi_max = params.get_one_float("phimax", 360);
    if (!(radius > 0) || !(z_max != z_min) || !(phi_max > 0) || !std::isfinite(radius) ||
        !std::isfinite(z_min) || !std::isfinite(z_max)) {
        warning(loc, "cylinder: no surface (radius, zmin..zmax or phimax is empty); skipped");
        return nullptr;
    }
    auto group = std::make_shared<ShapeGroup>();
    group->type = "cylinder";
    group->analytic = std::make_shared<Cylinder>(render_from_object, reverse_orientation, radius,
                                                 z_min, z_max, phi_max);
    return group;
}

// The shapes that are one group each.
std::shared_ptr<ShapeGroup> create_shape(const std::string &type, const Transform &render_from_object,
                                         bool reverse_orientation, const ParameterDictionary &params,
                                         const SourceLocation &loc) {
    if (type == "trianglemesh")
        return create_triangle_mesh(render_from_object, reverse_orientation, params, loc);
    if (type == "bilinearmesh")
        return create_bilinear_mesh(render_from_object, reverse_orientation, params, loc);
    if (type == "sphere") return create_sphere(render_from_object, reverse_orientation, params, loc);
    if (type == "disk") return create_disk(render_from_object, reverse_orientation, params, loc);
    if (type == "cylinder")
        return create_cylinder(render_from_object, reverse_orientation, params, loc);
    if (type == "curve") {
        auto group = std::make_shared<ShapeGroup>();
        group->type = "curve";
        group->curves = create_curves(render_from_object, reverse_orientation, params);
        return group;
    }
    // pbrt-v4's other shapes, and pbrt-v3's quadrics that v4 dropped.
    if (type == "loopsubdiv")
        return create_loop_subdivision(render_from_object, reverse_orientation, params, loc);
    for (const char *unsupported : {"cone", "paraboloid",
                                    "hyperboloid", "heightfield", "nurbs"})
        if (type == unsupported) {
            warning(loc, "shape \"" + type + "\" is not supported; skipped");
            return nullptr;
        }
    throw InputError(loc, "unknown shape type \"" + type + "\"");
}

} // namespace

std::vector<std::shared_ptr<ShapeGroup>> create_shapes(const std::string &type,
                                                       const Transform &render_from_object,
                                                       bool reverse_orientation,
                                                       const ParameterDictionary &params,
                                                       const SourceLocation &loc,
                                                       const FloatTexture *displacement) {
    if (type == "plymesh")
        return create_ply_mesh(render_from_object, reverse_orientation, params, loc, displacement);
    if (auto group = create_shape(type, render_from_object, reverse_orientation, params, loc))
        return {std::move(group)};
    return {};
}

} // namespace caustica
