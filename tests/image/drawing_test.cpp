// The figure writers: SVG text (well-formed, escaped, pictures as base64 PNG), the rasteriser (strokes,
// fills, text, pictures, colours back through the PNG encoder), the bitmap font, and the XML check the
// plot tests rely on (it must reject what a parser rejects).
#include <gtest/gtest.h>

#include "illum/image/bitmap_font.h"
#include "illum/image/drawing_io.h"
#include "illum/image/ldr.h"
#include "illum/image/rasterize.h"
#include "illum/image/svg.h"
#include "illum/image/tonemap.h"
#include "illum/util/error.h"
#include "xml_check.h"

namespace illum {
namespace {

TEST(XmlCheck, AcceptsWellFormedAndRejectsBroken) {
    EXPECT_TRUE(
        test::check_xml("<?xml version=\"1.0\"?>\n<a x=\"1\" y='2'><b/>t &amp; &#x3b8; &#952;</a>\n").ok);
    for (const char* bad : {"<a><b></a></b>", "<a>x & y</a>", "<a x=1/>", "<a/><b/>", "<a x=\"1\" x=\"2\"/>",
                            "<a>", "text<a/>", "<a x=\"<\"/>", "<a>&foo;</a>", "<a><?pi?></a>"}) {
        EXPECT_FALSE(test::check_xml(bad).ok) << bad;
    }
}

TEST(Svg, Base64) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

Drawing sample_drawing() {
    Drawing d;
    d.width = 120;
    d.height = 80;
    d.line({10, 10}, {110, 10}, {1, 0, 0}, 3);
    d.rectangle(20, 30, 40, 20, {0, 0, 1});
    d.text({60, 75}, "θ < 5 & \"ρ\" > 'x'", 10, TextAnchor::Middle);
    Image pic(2, 2, Color3(0.5f));
    d.add(Picture{pic, 80, 30, 20, 20});
    d.add(Stroke{{{10, 60}, {30, 70}, {50, 60}}, {0, 0.5f, 0}, 1, true, 4});
    return d;
}

TEST(Svg, WellFormedWithEscapedTextAndEmbeddedPicture) {
    std::string svg = to_svg(sample_drawing());
    test::XmlCheck x = test::check_xml(svg);
    ASSERT_TRUE(x.ok) << x.error;
    EXPECT_EQ(x.root, "svg");
    EXPECT_NE(svg.find("θ &lt; 5 &amp; &quot;ρ&quot; &gt; &apos;x&apos;"), std::string::npos);
    EXPECT_NE(svg.find("xlink:href=\"data:image/png;base64,iVBOR"), std::string::npos) << "a PNG's signature";
    EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
    EXPECT_NE(svg.find("viewBox=\"0 0 120 80\""), std::string::npos);
}

TEST(Rasterize, PaintsEachPrimitiveInItsColour) {
    Image img = rasterize(sample_drawing());
    ASSERT_EQ(img.width(), 120);
    ASSERT_EQ(img.height(), 80);
    // The red line (3 px wide about y = 10): full red at its centre, background far from it.
    Color3 on = img(60, 10), off = img(60, 20);
    EXPECT_NEAR(on.r, 1, 1e-3);
    EXPECT_NEAR(on.g, 0, 1e-3);
    EXPECT_NEAR(off.r, 1, 1e-3);
    EXPECT_NEAR(off.g, 1, 1e-3);
    // Inside the blue rectangle; the picture's grey 0.5 (linear display value).
    EXPECT_NEAR(img(40, 40).b, 1, 1e-3);
    EXPECT_NEAR(img(40, 40).r, 0, 1e-3);
    EXPECT_NEAR(img(90, 40).g, 0.5, 1e-3);
    // Text leaves ink around its anchor.
    double ink = 0;
    for (int y = 66; y < 78; ++y)
        for (int x = 20; x < 100; ++x) ink += 1 - img(x, y).g;
    EXPECT_GT(ink, 20);
    // A display colour comes back through the PNG encoder: 0.5 → code 128 (sRGB 188/255 ↔ linear 0.5).
    Drawing d;
    d.width = d.height = 4;
    d.background = Color3(0.5f);
    Image grey = rasterize(d);
    EXPECT_EQ(int(srgb8_encode(grey(1, 1).r)), 128);
    // Scale 2 doubles the size.
    EXPECT_EQ(rasterize(sample_drawing(), 2).width(), 240);
}

TEST(BitmapFont, EveryPrintableCharacterHasItsOwnGlyph) {
    const Glyph& box = glyph(U'\uFFFD');
    for (char32_t c = 33; c < 127; ++c) {
        const Glyph& g = glyph(c);
        bool differs = false, ink = false;
        for (int r = 0; r < kGlyphRows; ++r) {
            differs = differs || g.rows[r] != box.rows[r];
            ink = ink || g.rows[r] != 0;
        }
        EXPECT_TRUE(differs && ink) << "code point " << int(c);
    }
    auto cps = decode_utf8("aθ°\xff");
    ASSERT_EQ(cps.size(), 4u);
    EXPECT_EQ(cps[1], U'θ');
    EXPECT_EQ(cps[2], U'°');
    EXPECT_EQ(cps[3], U'\uFFFD');
    EXPECT_FLOAT_EQ(text_width("ab", 10), 11); // (2 × 6 - 1) units of 1 px
}

TEST(DrawingIo, WritesSvgAndPngAndRefusesOtherExtensions) {
    std::string dir = ::testing::TempDir();
    write_drawing(sample_drawing(), dir + "/d.svg");
    write_drawing(sample_drawing(), dir + "/d.png");
    EXPECT_THROW(write_drawing(sample_drawing(), dir + "/d.exr"), Error);
    EXPECT_TRUE(is_drawing_extension("x.SVG"));
    EXPECT_FALSE(is_drawing_extension("x.pdf"));
}

} // namespace
} // namespace illum
