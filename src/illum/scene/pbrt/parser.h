// Parser for the pbrt-v4 scene format (https://pbrt.org/fileformat-v4): produces a SceneDesc, plain data
// with every entity's source position. It parses only: meshes named by "plymesh" shapes are not read
// (see ply.h), materials and textures are not checked against known types. Every problem throws
// illum::Error naming file:line:column; recognised but unsupported features (media, motion blur,
// deprecated directives) add a line to SceneDesc::warnings.
//
// Semantics kept from pbrt-v4:
//  - transform directives post-multiply the current transform (CTM); Transform/ConcatTransform take 16
//    numbers in column-major order; the CTM at Camera is camera_from_world and defines the named
//    coordinate system "camera" (its inverse); WorldBegin resets the CTM and defines "world";
//  - AttributeBegin/End push and pop the whole graphics state; TransformBegin/End (deprecated) only the
//    CTM; ObjectBegin/End push and pop the graphics state too;
//  - shapes inside ObjectBegin/End keep the full CTM at the Shape (as pbrt-v4 does), and ObjectInstance
//    records the CTM at the use as world_from_instance: a shape of an instance is placed at
//    world_from_instance * world_from_object;
//  - NamedMaterial and ObjectInstance may name things defined later in the file (checked at the end);
//  - a scene must reach WorldBegin (possibly in an included file): one that ends before it is an error at
//    the end of the main file ("End of files before WorldBegin"), so an empty file is not a black image;
//  - relative file names resolve against the directory of the file that names them: Include/Import, and
//    string parameters named "filename" (and a material's "normalmap") of shapes, textures, lights,
//    materials and media (the Film's output "filename" is left as written); a "spectrum" string that
//    names an existing file relative to that directory is resolved too, other strings are kept (named
//    spectra such as "metal-Au-eta");
//  - ActiveTransform EndTime: transform directives are ignored (the start-time geometry is kept), with
//    a warning; TransformTimes is recorded as a warning only.
#pragma once

#include <string>

#include "illum/scene/scene_desc.h"

namespace illum {

struct ParseOptions {
    // The parser's warnings (SceneDesc::warnings) are errors instead: the first throws illum::Error at its
    // position. The CLI's --strict sets it, as it sets BuildOptions::strict for the builder's warnings.
    bool strict = false;
};

// Parses a scene file; SceneDesc::base_dir is the file's directory.
SceneDesc parse_pbrt_file(const std::string& path, const ParseOptions& options = {});

// Parses scene text held in memory; `virtual_filename` names it in errors and `base_dir` is where its
// relative file names (Include, "filename" parameters) resolve.
SceneDesc parse_pbrt_string(const std::string& text, const std::string& virtual_filename,
                            const std::string& base_dir, const ParseOptions& options = {});

} // namespace illum
