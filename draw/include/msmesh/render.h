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

/// Named viewing directions, for a mesh whose up axis is +y (RenderOptions::up turns them for
/// other up axes): `front` looks from +z, `right` from +x, `top` from +y (with −z up in the
/// picture), `iso` from the (1, 1, 1) octant.
enum class View { Iso, Front, Back, Left, Right, Top, Bottom };

/// "iso", "front", "back", "left", "right", "top", "bottom".
std::vector<std::string> view_names();
/// The view of a name from view_names(); throws InvalidInput (listing the names) otherwise.
View view_from_name(const std::string& name);

/// The world axis that points up in the picture. The views are defined for +y up; for another
/// axis the world is turned so that it takes the place of +y, with front still a side view:
///  - y: front looks from +z, right from +x (the default; OBJ, glTF, most scanners);
///  - z: front looks from −y, right from +x (CAD, STL, Blender);
///  - x: front looks from +z, right from −y;
///  - −x: front from +z, right from +y; −y: front from −z, right from +x; −z: front from +y,
///    right from +x (upside down).
enum class UpAxis { PosX, NegX, PosY, NegY, PosZ, NegZ };

/// "x", "-x", "y", "-y", "z", "-z".
std::vector<std::string> up_axis_names();
/// The axis of a name from up_axis_names() ("+x" too); throws InvalidInput otherwise.
UpAxis up_axis_from_name(const std::string& name);
/// The name of an axis ("x", "-y", ...).
std::string up_axis_name(UpAxis axis);

enum class Projection { Orthographic, Perspective };

struct RenderOptions {
  int width = 800, height = 600;  ///< output size in pixels, each in [1, 16384]
  View view = View::Iso;
  UpAxis up = UpAxis::PosY;  ///< world axis shown upwards
  /// Camera rotation from the named view: azimuth turns the camera about the up axis
  /// (counter-clockwise seen from above), then elevation raises it (towards the up axis; negative
  /// lowers it), both in degrees. 0 and 0 leave the view as named.
  double azimuth_deg = 0;
  double elevation_deg = 0;
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

/// The numeric RenderOptions with their ranges (parameters.h), shared by validate(), the CLI's
/// --size, --supersample, --line-width, --azimuth and --elevation and Python's keywords.
const ParameterTable<RenderOptions>& render_parameters();

/// What to draw on the mesh besides its shaded faces.
struct MeshStyle {
  Eigen::MatrixXd face_colors;  ///< empty, or #F by 3 RGB in [0,1] (shaded like the base colour)
  /// Empty, or #V by 3 RGB in [0,1]: colours of the vertices (a scan's own colours),
  /// interpolated across each face and shaded like the base colour. At most one of
  /// face_colors and vertex_colors may be given.
  Eigen::MatrixXd vertex_colors;
  /// #L by 2 vertex pairs: edges of F drawn as lines of RenderOptions::line_width, unshaded,
  /// on the faces next to them (so they are hidden exactly where those faces are).
  Eigen::MatrixXi lines;
  Eigen::MatrixXd line_colors;  ///< #L by 3 RGB in [0,1], or 1 by 3 for all lines (empty: black)
};

/// Renders (V, F) (#V by 3, #F by 3) into an options.width by options.height image. Throws
/// InvalidInput for an invalid mesh or options, face_colors or vertex_colors of the wrong size
/// (or both given), or a line that is not an edge of F (naming it). A mesh without faces gives the background.
Image render_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const MeshStyle& style = {},
                  const RenderOptions& options = {});

/// The edges of (V, F) whose dihedral angle exceeds angle_deg (#L by 2 vertex pairs, in the
/// edge order of build_topology), plus boundary edges when `boundary` is true.
Eigen::MatrixXi sharp_edges(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double angle_deg,
                            bool boundary = false);

}  // namespace msmesh
