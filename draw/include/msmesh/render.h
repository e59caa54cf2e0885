// Software rendering of triangle meshes into RGB images in memory, for figures and contact
// sheets (people judge a denoiser by looking). A small deterministic rasteriser: z-buffer,
// flat Lambert + ambient shading from a light fixed to the camera, optional coloured edge
// lines (features, edge field), orthographic or perspective camera with named views and
// automatic framing, s×s supersampling, white background.
//
// The rest of a figure: image.h (images, rectangles, panels), color_map.h (colour maps),
// text.h (a 5×7 bitmap font), color_bar.h (legends), png.h (PNG encoding to bytes).
// Nothing here touches files: the caller writes encode_png()'s bytes wherever it likes.
// Rendering is single-threaded and uses no global state, so the same input always gives the
// same pixels.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/image.h"
#include "msmesh/parameters.h"

namespace msmesh {

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
  double fov_deg = 30;   ///< perspective only: field of view in (0, 120) degrees (sets the distance)
  int supersample = 2;   ///< s: s×s samples per pixel, averaged (anti-aliasing); in [1, 4]
  double margin = 0.05;  ///< fraction of width/height left empty on each side, in [0, 0.45]
  double ambient = 0.3;  ///< shade = ambient + diffuse·max(0, n·l), both ≥ 0
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

/// The numeric RenderOptions with their ranges (parameters.h), shared by validate() and the
/// CLI's --size, --supersample and --line-width.
const ParameterTable<RenderOptions>& render_parameters();

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

}  // namespace msmesh
