// The pbrt-v4 parser: directives, parameter lists, transforms and graphics-state scoping.
#include "illum/scene/pbrt/parser.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"

namespace illum {
namespace {

SceneDesc parse(const std::string& text, const std::string& base_dir = "/scenes/here") {
    return parse_pbrt_string(text, "test.pbrt", base_dir);
}

void expect_matrix_near(const Matrix4& a, const Matrix4& b, double tol = 1e-6) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a(r, c), b(r, c), tol) << "at (" << r << ", " << c << ")";
}

void expect_inverse_consistent(const Transform& t) {
    expect_matrix_near(t.matrix() * t.inverse_matrix(), Matrix4::identity(), 1e-6);
}

Matrix4 rows(std::initializer_list<double> v) {
    Matrix4 m;
    int i = 0;
    for (double x : v) {
        m.m[i / 4][i % 4] = x;
        ++i;
    }
    return m;
}

void expect_point_near(Point3f a, Point3f b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(PbrtParser, OptionsAndCamera) {
    SceneDesc s = parse(R"(
        LookAt 0 0 0  0 0 1  0 1 0
        Camera "perspective" "float fov" [ 45 ]
        Film "rgb" "integer xresolution" 640 "integer yresolution" [ 480 ] "string filename" "out.exr"
        Sampler "halton" "integer pixelsamples" 16
        PixelFilter "box"
        Integrator "path" "integer maxdepth" [ 5 ]
        Accelerator "bvh" "integer maxnodeprims" 4
        ColorSpace "srgb"
        Option "bool disablepixeljitter" true
        Option "string rendercoordsys" "world"
        WorldBegin
    )");
    EXPECT_EQ(s.filename, "test.pbrt");
    EXPECT_EQ(s.base_dir, "/scenes/here");
    EXPECT_EQ(s.camera.type, "perspective");
    EXPECT_FLOAT_EQ(s.camera.params.get_float("fov", 0), 45);
    EXPECT_EQ(s.camera.loc.line, 3);
    EXPECT_EQ(s.camera.loc.column, 9);
    expect_matrix_near(s.camera.camera_from_world.matrix(), Matrix4::identity());
    EXPECT_EQ(s.film.type, "rgb");
    EXPECT_EQ(s.film.params.get_int("xresolution", 0), 640);
    EXPECT_EQ(s.film.params.get_int("yresolution", 0), 480);
    EXPECT_EQ(s.film.params.get_string("filename", ""), "out.exr"); // output names are not resolved
    EXPECT_EQ(s.sampler.type, "halton");
    EXPECT_EQ(s.sampler.params.get_int("pixelsamples", 0), 16);
    EXPECT_EQ(s.filter.type, "box");
    EXPECT_EQ(s.integrator.params.get_int("maxdepth", 0), 5);
    EXPECT_TRUE(s.options.get_bool("disablepixeljitter", false));
    EXPECT_EQ(s.options.get_string("rendercoordsys", ""), "world");
    EXPECT_EQ(s.color_space, "srgb");
    EXPECT_TRUE(s.warnings.empty());
}

TEST(PbrtParser, ParameterTypes) {
    SceneDesc s = parse(R"(WorldBegin
        Shape "test"
            "float f" [ 1 2.5 ] "integer i" [ -3 4 ] "bool b1" true "bool b2" [ "false" ] "bool b3" [ true false ]
            "string s" "hello" "rgb c" [ .1 .2 .3 ] "color c2" [ 1 1 1 ]
            "spectrum named" "metal-Au-eta" "spectrum sampled" [ 300 .3 800 .6 ] "blackbody bb" 5500
            "point2 p2" [ 1 2 3 4 ] "point3 p3" [ 1 2 3 ] "point p" [ 4 5 6 ] "vector3 v3" [ 0 0 1 ]
            "vector v" [ 1 0 0 ] "normal n" [ 0 1 0 ] "normal3 n3" [ 0 0 1 ] "texture tex" "checks"
    )");
    ASSERT_EQ(s.shapes.size(), 1u);
    const ParamSet& ps = s.shapes[0].params;
    EXPECT_EQ(ps.get_floats("f"), (std::vector<float>{1, 2.5f}));
    EXPECT_EQ(ps.get_ints("i"), (std::vector<int>{-3, 4}));
    EXPECT_TRUE(ps.get_bool("b1", false));
    EXPECT_FALSE(ps.get_bool("b2", true));
    EXPECT_EQ(ps.find("b3")->bools, (std::vector<bool>{true, false}));
    EXPECT_EQ(ps.get_string("s", ""), "hello");
    EXPECT_EQ(ps.find("c")->type, ParamType::RGB);
    EXPECT_EQ(ps.find("c2")->type, ParamType::RGB);
    EXPECT_EQ(ps.find("named")->type, ParamType::Spectrum);
    EXPECT_EQ(ps.find("named")->strings, (std::vector<std::string>{"metal-Au-eta"}));
    EXPECT_EQ(ps.find("sampled")->numbers, (std::vector<double>{300, .3, 800, .6}));
    const Param* bb = ps.find("bb");
    EXPECT_EQ(bb->type, ParamType::Spectrum);
    EXPECT_EQ(bb->strings, (std::vector<std::string>{"blackbody"}));
    EXPECT_EQ(bb->numbers, (std::vector<double>{5500}));
    EXPECT_EQ(ps.get_point2s("p2").size(), 2u);
    EXPECT_EQ(ps.find("p3")->type, ParamType::Point3);
    EXPECT_EQ(ps.find("p")->type, ParamType::Point3);
    EXPECT_EQ(ps.find("v3")->type, ParamType::Vector3);
    EXPECT_EQ(ps.find("v")->type, ParamType::Vector3);
    EXPECT_EQ(ps.find("n")->type, ParamType::Normal);
    EXPECT_EQ(ps.find("n3")->type, ParamType::Normal);
    EXPECT_EQ(ps.get_texture("tex"), "checks");
    EXPECT_EQ(ps.find("f")->loc.line, 3);
    EXPECT_EQ(ps.find("f")->loc.column, 13);
}

TEST(PbrtParser, TransformDirectives) {
    SceneDesc s = parse(R"(WorldBegin
        AttributeBegin
          Translate 1 2 3
          Shape "a"
        AttributeEnd
        AttributeBegin
          Scale 2 3 4
          Shape "b"
        AttributeEnd
        AttributeBegin
          Rotate 90 0 0 1
          Shape "c"
        AttributeEnd
        AttributeBegin
          Translate 1 0 0
          Scale 2 2 2
          Shape "d"
        AttributeEnd
        AttributeBegin
          Transform [ 1 0 0 0  0 1 0 0  0 0 1 0  5 6 7 1 ]
          Shape "e"
        AttributeEnd
        AttributeBegin
          Translate 1 0 0
          ConcatTransform [ 2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1 ]
          Shape "f"
          Identity
          Shape "g"
        AttributeEnd
        Shape "h"
    )");
    ASSERT_EQ(s.shapes.size(), 8u);
    for (auto& sh : s.shapes) expect_inverse_consistent(sh.world_from_object);
    auto T = [&](int i) { return s.shapes[i].world_from_object; };
    expect_point_near(T(0)(Point3f(0, 0, 0)), Point3f(1, 2, 3));
    expect_point_near(T(1)(Point3f(1, 1, 1)), Point3f(2, 3, 4));
    expect_point_near(T(2)(Point3f(1, 0, 0)), Point3f(0, 1, 0)); // right-handed rotation about +z
    expect_point_near(T(3)(Point3f(1, 0, 0)), Point3f(3, 0, 0)); // Translate * Scale: scale first
    expect_matrix_near(T(4).matrix(), rows({1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1}));
    expect_point_near(T(5)(Point3f(1, 0, 0)), Point3f(3, 0, 0));
    EXPECT_TRUE(T(6).is_identity());
    EXPECT_TRUE(T(7).is_identity()); // AttributeEnd restored the CTM
}

TEST(PbrtParser, TransformColumnMajorIsTransposed) {
    // A general matrix: the file lists it column by column.
    SceneDesc s = parse(R"(Transform [ 1 5 9 0  2 6 10 0  3 7 12 0  4 8 11 1 ]
        Camera "perspective" WorldBegin)");
    expect_matrix_near(s.camera.camera_from_world.matrix(),
                       rows({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 11, 0, 0, 0, 1}));
    expect_inverse_consistent(s.camera.camera_from_world);
}

TEST(PbrtParser, LookAtAndCameraCoordinateSystem) {
    SceneDesc s = parse(R"(
        LookAt 1 2 3   1 2 10   0 1 0
        Camera "perspective"
        WorldBegin
        AttributeBegin
          CoordSysTransform "camera"
          Shape "sphere"
        AttributeEnd
        Translate 0 0 5
        CoordinateSystem "mine"
        Identity
        AttributeBegin
          CoordSysTransform "mine"
          Shape "sphere"
          CoordSysTransform "world"
          Shape "sphere"
        AttributeEnd
    )");
    const Transform& cfw = s.camera.camera_from_world;
    expect_point_near(cfw(Point3f(1, 2, 3)), Point3f(0, 0, 0));
    expect_point_near(cfw(Point3f(1, 2, 4)), Point3f(0, 0, 1)); // +z towards the target
    expect_point_near(cfw(Point3f(1, 3, 3)), Point3f(0, 1, 0)); // +y up
    expect_point_near(cfw(Point3f(2, 2, 3)), Point3f(1, 0, 0)); // +x = up x forward (left-handed)
    ASSERT_EQ(s.shapes.size(), 3u);
    expect_matrix_near(s.shapes[0].world_from_object.matrix(), cfw.inverse_matrix());
    expect_point_near(s.shapes[1].world_from_object(Point3f(0, 0, 0)), Point3f(0, 0, 5));
    EXPECT_TRUE(s.shapes[2].world_from_object.is_identity());
}

TEST(PbrtParser, WorldBeginResetsTransform) {
    SceneDesc s = parse(R"(Scale -1 1 1
        LookAt 278 273 -800  278 273 0  0 1 0
        Camera "perspective"
        WorldBegin
        Shape "sphere")");
    EXPECT_TRUE(s.shapes[0].world_from_object.is_identity());
    // The mirror is part of camera_from_world.
    EXPECT_TRUE(s.camera.camera_from_world.swaps_handedness());
}

TEST(PbrtParser, AttributeScopingOfGraphicsState) {
    SceneDesc s = parse(R"(WorldBegin
        Material "diffuse" "rgb reflectance" [ .1 .2 .3 ]
        AttributeBegin
          ReverseOrientation
          Material "conductor"
          AreaLightSource "diffuse" "rgb L" [ 17 12 4 ]
          MediumInterface "fog" "air"
          Shape "a"
        AttributeEnd
        Shape "b"
        TransformBegin
          Translate 0 1 0
          NamedMaterial "gold"
          Shape "c"
        TransformEnd
        Shape "d"
        MakeNamedMaterial "gold" "string type" "conductor" "spectrum eta" "metal-Au-eta"
    )");
    ASSERT_EQ(s.shapes.size(), 4u);
    ASSERT_EQ(s.materials.size(), 3u);
    EXPECT_EQ(s.materials[0].type, "diffuse");
    EXPECT_EQ(s.materials[1].type, "conductor");
    EXPECT_EQ(s.materials[2].name, "gold");
    EXPECT_EQ(s.materials[2].type, "conductor");
    EXPECT_FALSE(s.materials[2].params.has("type"));
    EXPECT_EQ(s.named_materials.at("gold"), 2);

    const ShapeDesc& a = s.shapes[0];
    EXPECT_TRUE(a.reverse_orientation);
    EXPECT_EQ(a.material.index, 1);
    ASSERT_EQ(a.area_light, 0);
    ASSERT_EQ(s.area_lights.size(), 1u);
    EXPECT_EQ(s.area_lights[0].type, "diffuse");
    EXPECT_EQ(s.area_lights[0].params.get_rgb("L")->r, 17.0f);
    EXPECT_EQ(a.inside_medium, "fog");
    EXPECT_EQ(a.outside_medium, "air");

    const ShapeDesc& b = s.shapes[1];
    EXPECT_FALSE(b.reverse_orientation);
    EXPECT_EQ(b.material.index, 0);
    EXPECT_EQ(b.area_light, -1);
    EXPECT_EQ(b.inside_medium, "");

    const ShapeDesc& c = s.shapes[2];
    EXPECT_EQ(c.material.index, -1);
    EXPECT_EQ(c.material.name, "gold");
    expect_point_near(c.world_from_object(Point3f(0, 0, 0)), Point3f(0, 1, 0));

    // TransformEnd restores only the CTM: the material set inside stays.
    const ShapeDesc& d = s.shapes[3];
    EXPECT_TRUE(d.world_from_object.is_identity());
    EXPECT_EQ(d.material.name, "gold");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("TransformBegin"), std::string::npos);
    EXPECT_NE(s.warnings[0].find("test.pbrt:11:"), std::string::npos);
}

TEST(PbrtParser, DefaultMaterialIsUnset) {
    SceneDesc s = parse("WorldBegin Shape \"sphere\"");
    EXPECT_EQ(s.shapes[0].material.index, -1);
    EXPECT_EQ(s.shapes[0].material.name, "");
}

TEST(PbrtParser, LightsTexturesAndAttributes) {
    SceneDesc s = parse(R"(WorldBegin
        Translate 0 10 0
        LightSource "point" "rgb I" [ 1 1 1 ]
        Texture "checks" "spectrum" "checkerboard" "float uscale" 4
        Texture "bumps" "float" "imagemap" "string filename" "tex/bump.png"
        Material "diffuse" "string normalmap" "../nm.png"
        Attribute "shape" "float radius" 2
        Attribute "light" "float scale" 3
        Shape "sphere"
        Shape "sphere" "float radius" 5
        LightSource "spot"
    )");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].type, "point");
    expect_point_near(s.lights[0].world_from_light(Point3f(0, 0, 0)), Point3f(0, 10, 0));
    EXPECT_FALSE(s.lights[0].params.has("scale"));
    EXPECT_FLOAT_EQ(s.lights[1].params.get_float("scale", 0), 3);
    ASSERT_EQ(s.textures.size(), 2u);
    EXPECT_EQ(s.spectrum_textures.at("checks"), 0);
    EXPECT_EQ(s.float_textures.at("bumps"), 1);
    EXPECT_EQ(s.textures[0].type, "checkerboard");
    EXPECT_EQ(s.textures[0].value_type, "spectrum");
    expect_point_near(s.textures[0].world_from_texture(Point3f(0, 0, 0)), Point3f(0, 10, 0));
    EXPECT_EQ(s.textures[1].params.get_string("filename", ""), "/scenes/here/tex/bump.png");
    EXPECT_EQ(s.materials[0].params.get_string("normalmap", ""), "/scenes/nm.png");
    ASSERT_EQ(s.shapes.size(), 2u);
    EXPECT_FLOAT_EQ(s.shapes[0].params.get_float("radius", 0), 2);
    EXPECT_FLOAT_EQ(s.shapes[1].params.get_float("radius", 0), 5);
}

TEST(PbrtParser, FilenamesResolveAgainstTheNamingFile) {
    test::TempDir dir("resolve");
    dir.write("sub/part.pbrt", "Shape \"plymesh\" \"string filename\" \"models/a.ply\"\n"
                               "Shape \"plymesh\" \"string filename\" \"/abs/b.ply\"\n");
    dir.write("main.pbrt", "WorldBegin\nNamedMaterial \"m\"\nInclude \"sub/part.pbrt\"\n"
                           "Shape \"plymesh\" \"string filename\" \"c.ply\"\n"
                           "MakeNamedMaterial \"m\" \"string type\" \"diffuse\"\n");
    SceneDesc s = parse_pbrt_file(dir.file("main.pbrt"));
    EXPECT_EQ(s.base_dir, dir.path());
    ASSERT_EQ(s.shapes.size(), 3u);
    EXPECT_EQ(s.shapes[0].params.get_string("filename", ""), dir.file("sub/models/a.ply"));
    EXPECT_EQ(s.shapes[1].params.get_string("filename", ""), "/abs/b.ply");
    EXPECT_EQ(s.shapes[2].params.get_string("filename", ""), dir.file("c.ply"));
    // Included text shares the graphics state and carries its own positions.
    EXPECT_EQ(s.shapes[0].material.name, "m");
    EXPECT_EQ(s.shapes[0].loc.file, dir.file("sub/part.pbrt"));
    EXPECT_EQ(s.shapes[0].loc.line, 1);
    EXPECT_EQ(s.shapes[2].loc.file, dir.file("main.pbrt"));
    EXPECT_EQ(s.shapes[2].loc.line, 4);
}

TEST(PbrtParser, ImportIsLikeInclude) {
    test::TempDir dir("import");
    dir.write("geo.pbrt", "Shape \"sphere\"\n");
    SceneDesc s =
        parse_pbrt_string("WorldBegin Translate 1 0 0 Import \"geo.pbrt\"", "main.pbrt", dir.path());
    ASSERT_EQ(s.shapes.size(), 1u);
    expect_point_near(s.shapes[0].world_from_object(Point3f(0, 0, 0)), Point3f(1, 0, 0));
}

TEST(PbrtParser, ObjectInstances) {
    SceneDesc s = parse(R"(WorldBegin
        AttributeBegin
          ObjectBegin "thing"
            Material "diffuse"
            Translate 0 0 1
            Shape "sphere"
            AreaLightSource "diffuse"
            Shape "disk"
          ObjectEnd
        AttributeEnd
        Shape "cylinder"
        Translate 5 0 0
        ObjectInstance "thing"
        ObjectInstance "later"
        ObjectBegin "later" Shape "sphere" ObjectEnd
    )");
    ASSERT_EQ(s.shapes.size(), 1u);
    EXPECT_EQ(s.shapes[0].material.index, -1); // ObjectEnd restored the graphics state
    ASSERT_EQ(s.instances.size(), 2u);
    const InstanceDefinition& def = s.instances.at("thing");
    EXPECT_EQ(def.name, "thing");
    EXPECT_EQ(def.loc.line, 3);
    ASSERT_EQ(def.shapes.size(), 2u);
    expect_point_near(def.shapes[0].world_from_object(Point3f(0, 0, 0)), Point3f(0, 0, 1));
    EXPECT_EQ(def.shapes[0].material.index, 0);
    EXPECT_EQ(def.shapes[1].area_light, -1); // area lights in instances are not supported
    ASSERT_EQ(s.instance_uses.size(), 2u);
    EXPECT_EQ(s.instance_uses[0].name, "thing");
    expect_point_near(s.instance_uses[0].world_from_instance(Point3f(0, 0, 0)), Point3f(5, 0, 0));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("area lights"), std::string::npos);
}

TEST(PbrtParser, MediaAreRecordedTheCameraMoves) {
    SceneDesc s = parse(R"(
        MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [ 1 1 1 ]
        MediumInterface "" "fog"
        ActiveTransform EndTime
        Translate 100 0 0
        ActiveTransform All
        TransformTimes 0 1
        Camera "perspective"
        WorldBegin
        MakeNamedMedium "smoke" "string type" "uniformgrid"
    )");
    ASSERT_EQ(s.media.size(), 2u);
    EXPECT_EQ(s.media.at("fog").type, "homogeneous");
    EXPECT_FALSE(s.media.at("fog").params.has("type"));
    EXPECT_EQ(s.camera.medium, "fog");
    // The camera moves: its start transform is the identity, its end one translates by 100.
    EXPECT_TRUE(s.camera.camera_from_world.is_identity());
    ASSERT_TRUE(s.camera.motion.animated);
    expect_point_near(s.camera.motion.end(Point3f(0, 0, 0)), Point3f(100, 0, 0));
    EXPECT_EQ(s.camera.motion.start_time, 0);
    EXPECT_EQ(s.camera.motion.end_time, 1);
    EXPECT_TRUE(s.warnings.empty()); // the media made before the motion do not move
}

// pbrt-v4's two current transforms: ActiveTransform picks which of them the transform directives change,
// TransformTimes gives their times, and a shape, instance or camera whose two transforms differ moves.
TEST(PbrtParser, ActiveTransformAndTransformTimes) {
    SceneDesc s = parse(R"(
        TransformTimes 0.25 2
        WorldBegin
        Translate 1 0 0
        AttributeBegin
          ActiveTransform StartTime
          Translate 0 1 0
          ActiveTransform EndTime
          Translate 0 0 5
          Shape "sphere"
        AttributeEnd
        Shape "sphere"
        AttributeBegin
          ActiveTransform EndTime
          Rotate 90 0 0 1
          ObjectInstance "thing"
        AttributeEnd
        ObjectBegin "thing"
          Shape "sphere"
        ObjectEnd
    )");
    ASSERT_EQ(s.shapes.size(), 2u);
    const ShapeDesc& moving = s.shapes[0];
    expect_point_near(moving.world_from_object(Point3f(0, 0, 0)), Point3f(1, 1, 0));
    ASSERT_TRUE(moving.motion.animated);
    expect_point_near(moving.motion.end(Point3f(0, 0, 0)), Point3f(1, 0, 5));
    EXPECT_EQ(moving.motion.start_time, 0.25);
    EXPECT_EQ(moving.motion.end_time, 2);
    // AttributeEnd restored both transforms and ActiveTransform All.
    EXPECT_FALSE(s.shapes[1].motion.animated);
    expect_point_near(s.shapes[1].world_from_object(Point3f(0, 0, 0)), Point3f(1, 0, 0));
    ASSERT_EQ(s.instance_uses.size(), 1u);
    ASSERT_TRUE(s.instance_uses[0].motion.animated);
    expect_point_near(s.instance_uses[0].motion.end(Point3f(1, 0, 0)), Point3f(1, 1, 0));
    EXPECT_TRUE(s.warnings.empty());
}

// A scene of nothing but its world (no options, no shapes) is valid: every option has its default.
// (Empty input is an error, as in pbrt-v4: see parser_errors_test.cpp.)
TEST(PbrtParser, CommentsAndAnEmptyWorld) {
    SceneDesc s = parse("# nothing here\n\nWorldBegin\n");
    EXPECT_TRUE(s.shapes.empty());
    EXPECT_EQ(s.camera.type, "");
}

} // namespace
} // namespace illum
