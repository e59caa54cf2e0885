// Software rendering of triangle meshes into RGB images in memory, for figures and contact
// sheets (people judge a denoiser by looking). A small deterministic rasteriser: z-buffer,
// flat Lambert + ambient shading from a light fixed to the camera, optional coloured edge
// lines (features, edge field), orthographic or perspective camera with named views and
// automatic framing, s×s supersampling, white background. Plus the 2D pieces of a figure:
// a 5×7 bitmap font, colour bars, panels side by side, and PNG encoding to bytes.
//
// Nothing here touches files: the caller writes encode_png()'s bytes wherever it likes.
// Rendering is single-threaded and uses no global state, so the same input always gives the
// same pixels.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace msmesh {

// ---------------------------------------------------------------------------------------
// Images
// ---------------------------------------------------------------------------------------

/// An 8-bit RGB image: rows top to bottom, 3 bytes (R, G, B) per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width·height·3 bytes

  Image() = default;
  /// A width by height image filled with `color` (RGB in [0,1]; default white).
  Image(int width, int height, const Eigen::Vector3d& color = Eigen::Vector3d::Ones());

  /// Colour of pixel (x, y) in [0,1]; (0,0) is the top-left pixel.
  Eigen::Vector3d pixel(int x, int y) const;
  /// Sets pixel (x, y) to `color` (clamped to [0,1]); ignores pixels outside the image.
  void set(int x, int y, const Eigen::Vector3d& color);
  bool operator==(const Image& o) const { return width == o.width && height == o.height && rgb == o.rgb; }
  bool operator!=(const Image& o) const { return !(*this == o); }
};

// ---------------------------------------------------------------------------------------
// Rendering a mesh
// ---------------------------------------------------------------------------------------

/// Named viewing directions. World axes: +y is up. `front` looks from +z, `right` from +x,
/// `top` from +y (with −z up in the picture), `iso` from the (1, 1, 1) octant.
enum class View { Iso, Front, Back, Left, Right, Top, Bottom };

/// "iso", "front", "back", "left", "right", "top", "bottom".
std::vector<std::string> view_names();
/// The view of a name from view_names(); throws InvalidInput (listing the names) otherwise.
View view_from_name(const std::string& name);

enum class Projection { Orthographic, Perspective };

struct RenderOptions {
  int width = 800, height = 600;  ///< output size in pixels, each in [1, 16384]
  View view = View::Iso;
  Projection projection = Projection::Orthographic;
  double fov_deg = 30;    ///< perspective only: field of view in (0, 120) degrees (sets the distance)
  int supersample = 2;    ///< s: s×s samples per pixel, averaged (anti-aliasing); in [1, 4]
  double margin = 0.05;   ///< fraction of width/height left empty on each side, in [0, 0.45]
  double ambient = 0.3;   ///< shade = ambient + diffuse·max(0, n·l), both ≥ 0
  double diffuse = 0.7;
  /// Light direction in camera coordinates (x right, y up, z towards the viewer), normalised
  /// inside: upper left, in front. Off the view axis, so that the three visible faces of a cube
  /// seen in the iso view get three different shades. Faces are lit on both sides.
  Eigen::Vector3d light = Eigen::Vector3d(-0.4, 0.55, 1.0);
  Eigen::Vector3d background = Eigen::Vector3d::Ones();         ///< RGB in [0,1]
  Eigen::Vector3d base_color = Eigen::Vector3d(0.8, 0.8, 0.8);  ///< face colour when none given
  double line_width = 1.5;  ///< width of MeshStyle::lines in output pixels, in (0, 20]
  /// Framing: the camera fits these points (#P by 3) into the picture. Empty: the vertices of
  /// the mesh's faces. Pass the vertices of several meshes to render them at the same scale
  /// and position (side-by-side comparisons).
  Eigen::MatrixXd frame_points;
  /// Throws InvalidInput naming the bad parameter and its value.
  void validate() const;
};

/// What to draw on the mesh besides its shaded faces.
struct MeshStyle {
  Eigen::MatrixXd face_colors;  ///< empty, or #F by 3 RGB in [0,1] (shaded like the base colour)
  /// #L by 2 vertex pairs: edges of F drawn as lines of RenderOptions::line_width, unshaded,
  /// on the faces next to them (so they are hidden exactly where those faces are).
  Eigen::MatrixXi lines;
  Eigen::MatrixXd line_colors;  ///< #L by 3 RGB in [0,1], or 1 by 3 for all lines (empty: black)
};

/// Renders (V, F) (#V by 3, #F by 3) into an options.width by options.height image. Throws
/// InvalidInput for an invalid mesh or options, face_colors of the wrong size, or a line that
/// is not an edge of F (naming it). A mesh without faces gives the background.
Image render_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const MeshStyle& style = {},
                  const RenderOptions& options = {});

/// The edges of (V, F) whose dihedral angle exceeds angle_deg (#L by 2 vertex pairs, in the
/// edge order of build_topology), plus boundary edges when `boundary` is true.
Eigen::MatrixXi sharp_edges(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double angle_deg,
                            bool boundary = false);

// ---------------------------------------------------------------------------------------
// Colour maps (x in [0,1], values outside are clamped; RGB in [0,1])
// ---------------------------------------------------------------------------------------

using ColorMap = std::function<Eigen::Vector3d(double)>;

/// Sequential map for errors (ColorBrewer YlOrRd, designed for perception and colour-blind
/// safe): light yellow (0, shaded faces still read as a shape) to dark red (1).
Eigen::Vector3d heat_color(double x);

/// Distinct colours for labels ≥ 0: hues stepped by the golden ratio (the same colours as the
/// faces of `msmesh segment`'s .ply output).
Eigen::Vector3d label_color(int label);

// ---------------------------------------------------------------------------------------
// 2D drawing: text, colour bars, panels
// ---------------------------------------------------------------------------------------

/// Fills the rectangle [x, x+w) × [y, y+h), clipped to the image.
void fill_rect(Image& image, int x, int y, int w, int h, const Eigen::Vector3d& color);

/// Copies `src` into `dst` with its top-left corner at (x, y), clipped.
void blit(Image& dst, const Image& src, int x, int y);

/// Height in pixels of a line of text drawn at `scale` (8·scale: 7 rows and a descender row).
int text_height(int scale = 1);
/// Width in pixels of `text` drawn at `scale` (6·scale per character, minus the last gap).
int text_width(const std::string& text, int scale = 1);
/// Draws `text` (printable ASCII; UTF-8 "°" and "×" too; anything else shows as "?") with a
/// built-in 5×7 bitmap font, each font pixel a scale×scale block, top-left corner at (x, y).
void draw_text(Image& image, int x, int y, const std::string& text, const Eigen::Vector3d& color, int scale = 1);

/// A horizontal colour bar with tick labels, for a figure's legend.
struct ColorBar {
  ColorMap map;         ///< colours of [0,1]
  double min = 0, max = 1;  ///< the values at the two ends (labels)
  int ticks = 3;        ///< labelled ticks, evenly spaced, ends included (≥ 2)
  std::string title;    ///< drawn left of the bar, e.g. "angle error (deg)"
  bool max_is_clamped = false;  ///< label the top end ">=max" (larger values share its colour)
};

/// The formatted tick label of a value: at most 3 significant digits, no exponent for
/// values in [1e-3, 1e5) ("0", "0.25", "12.5", "1500").
std::string format_tick(double value);

/// Draws `bar` into the rectangle (x, y, w, h) of `image`: the title on the left, then the
/// gradient with a dark frame and ticks, labels under it. Text at `scale`. Needs h ≥
/// 2·text_height(scale) + 6·scale to fit; less is clipped.
void draw_color_bar(Image& image, int x, int y, int w, int h, const ColorBar& bar, int scale = 1);

/// Lays `panels` out left to right, `gap` pixels apart, on `background`, tops aligned.
Image hstack(const std::vector<Image>& panels, int gap = 0, const Eigen::Vector3d& background = Eigen::Vector3d::Ones());
/// Lays `panels` out top to bottom, `gap` pixels apart, left aligned.
Image vstack(const std::vector<Image>& panels, int gap = 0, const Eigen::Vector3d& background = Eigen::Vector3d::Ones());

// ---------------------------------------------------------------------------------------
// PNG
// ---------------------------------------------------------------------------------------

/// The bytes of a PNG file of `image` (8-bit RGB, no interlace; per-row adaptive filters,
/// deflate with fixed Huffman codes and LZ77 matching: a self-contained encoder, no zlib).
/// Deterministic. Throws InvalidInput for an empty image or one whose rgb has the wrong size.
std::vector<std::uint8_t> encode_png(const Image& image);

}  // namespace msmesh
