// filter_irregular: the one place that says what each filter is (filter_spec.h): name,
// pymeshlab name, help, category, parameters and apply function. Adding a filter or a
// parameter is one edit here; both MeshLab adapters read this list. Parameter names are part
// of users' .mlx scripts and Python calls: CHANGELOG.md lists every rename or removal.
#include "filter_spec.h"
#include "filters.h"

namespace filter_irregular {

namespace {

ParamSpec Bool(const char* name, bool def, const char* label, const char* help) {
  ParamSpec p;
  p.name = name;
  p.type = ParamType::Bool;
  p.defaultValue = def ? 1 : 0;
  p.label = label;
  p.help = help;
  return p;
}

ParamSpec Int(const char* name, int def, int lo, int hi, const char* label, const char* help) {
  ParamSpec p;
  p.name = name;
  p.type = ParamType::Int;
  p.defaultValue = def;
  p.minValue = lo;
  p.maxValue = hi;
  p.label = label;
  p.help = help;
  return p;
}

ParamSpec Float(const char* name, double def, double lo, double hi, const char* label, const char* help) {
  ParamSpec p = Int(name, 0, 0, 0, label, help);
  p.type = ParamType::Float;
  p.defaultValue = def;
  p.minValue = lo;
  p.maxValue = hi;
  return p;
}

ParamSpec Enum(const char* name, int def, std::vector<std::string> values, const char* label, const char* help) {
  ParamSpec p;
  p.name = name;
  p.type = ParamType::Enum;
  p.defaultValue = def;
  p.enumValues = std::move(values);
  p.label = label;
  p.help = help;
  return p;
}

ParamSpec Percentage(const char* name, double def, const char* label, const char* help) {
  ParamSpec p;
  p.name = name;
  p.type = ParamType::Percentage;
  p.defaultValue = def;
  p.label = label;
  p.help = help;
  return p;
}

ParamSpec Point3(const char* name, const char* label, const char* help) {
  ParamSpec p;
  p.name = name;
  p.type = ParamType::Point3;
  p.label = label;
  p.help = help;
  return p;
}

// Neighbour directions can be at most the valence; 63 is far above any real one.
const int kMaxDirection = 63;

ParamSpec RelaxAfterEditing() {
  return Bool("relax", true, "Relax after editing",
              "Local relaxation of the 2-ring around each step, projected onto the surface as it was before the "
              "filter (paper sec. 8).");
}

// Every editing filter, last: the legend, or the user's own colours and quality kept.
ParamSpec Colorize() {
  return Bool("colorize", true, "Colour by valence",
              "Paint the valence legend (v5 blue, v7 orange, v8 red, ...) and write the valence into vertex quality. "
              "Off: the vertex colours and quality you had are kept (a vertex an edit creates takes those of the "
              "vertex it was split from).");
}

std::vector<FilterSpec> MakeCatalog() {
  std::vector<FilterSpec> c;
  FilterSpec f;

  f = FilterSpec();
  f.id = kAnalyze;
  f.name = "Irregular Vertices: Analyze";
  f.pythonName = "compute_irregular_vertex_analysis";
  f.classes = kQuality | kMeasure | kSelection;
  f.changesConnectivity = false;
  f.info =
      "Colours vertices by valence (v3- purple, v4 cyan, v5 blue, v6 grey, v7 orange, v8 red, v9+ dark red; "
      "boundary vertices by valence + 6 - their regular valence, so regular boundary vertices are grey), writes "
      "the valence "
      "into vertex quality, optionally selects irregular vertices, and logs the valence histogram, the irregular "
      "count, Euler characteristic, genus, boundary loops and whether the discrete Gauss-Bonnet identity "
      "sum(6 - valence) + sum_boundary(4 - valence) = 6 chi holds (Li et al., Editing Operations for Irregular "
      "Vertices in Triangle Meshes, eq. 2). A boundary vertex is regular at valence round(corner angle / 60) + 1, "
      "the corner angle being the sum of its face angles: 4 on a smooth stretch (150 to 210 degrees), 3 at a "
      "120 degree corner, 2 at 60 degrees, 5 at 240. Returns the counts (pymeshlab: a dict; boundary_irregular: "
      "boundary vertices irregular by that rule, boundary_corners: boundary vertices whose regular valence is "
      "not 4). Refuses non-manifold or "
      "polygonal meshes without changing them.";
  f.params = {
      Enum("select", 1, {"None", "All irregular", "Only valence"}, "Select vertices",
           "Replace the vertex selection: None keeps it as it is; All irregular selects every vertex of valence != 6 "
           "(boundary: != the regular valence of its corner); Only valence selects the vertices of the valence below "
           "(boundary vertices count as "
           "valence + 6 - their regular valence, i.e. valence + 2 on a smooth stretch)."),
      Int("valence", 5, 0, 1000, "Valence to select",
          "Used with 'Only valence': select the vertices of this (interior-equivalent) valence."),
      Bool("colorize", true, "Colour by valence",
           "Paint vertices with the plugin's valence legend (v5 blue, v7 orange, v8 red, ...)."),
  };
  f.apply = ApplyAnalyze;
  c.push_back(f);

  f = FilterSpec();
  f.id = kAtomic;
  f.name = "Irregular Vertices: Atomic Operation";
  f.pythonName = "meshing_irregular_atomic_operation";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Applies one atomic operation of Li et al. (sec. 6.1-6.2) to the selected vertices (select them with the "
      "Analyze filter, by hand, or with 'Conditional Vertex Selection'):<br>"
      "<b>5-7 pair move</b> (fig. 6): select an adjacent v5 and v7; direction 0..5 is the k-th of the six moves "
      "counted counter-clockwise (seen from outside) from the v5-to-v7 edge, by the direction in which the pair "
      "moves: 0 along that edge (vertex split), 1 (edge flip), 2 (collapse), 3 (collapse), 4 (flip), 5 (split).<br>"
      "<b>v5/v7 move with 5-7 pair generation</b> (fig. 7): select one v5 or v7, and optionally one of its "
      "neighbours as the reference edge. Direction k moves the vertex into the k-th 60-degree sector counted "
      "counter-clockwise from the reference edge, measured in the vertex's tangent plane (sector k is centred "
      "on 60k degrees); with no neighbour selected, direction 0 is the model's +X axis projected into the tangent "
      "plane (+Y if the plane faces X). The vertex moves to the neighbour in that sector (a v5, which has five "
      "edges, moves into a new vertex made by a vertex split when its sector holds none) and leaves an adjacent "
      "5-7 pair. 'Graph operation' and 'Side of the new pair' choose among the configurations: a v5 by flip, "
      "collapse or split, a v7 by flip or split (no collapse moves a v7), each with the new pair on either side.<br>"
      "<b>v5/v7 move with 5-7 pair removal</b>: select an adjacent 5-5-7 or 5-7-7 triple; it becomes one v5 or v7 "
      "(triple cancellation; flips, collapses, then splits are tried).<br>"
      "<b>5-5-7-7 generation</b> (fig. 8) by flip, by split, or by collapse and split (the paper's two-operation "
      "configuration through a v8): select one regular vertex, and optionally a neighbour as reference edge; "
      "direction k: the edge the operation is built on (flipped, split or collapsed) lies in the k-th 60-degree "
      "sector from the reference.<br>"
      "<b>5-5-7-7 removal</b>: select the four vertices of a quadruple (fig. 8, any of the three variants).<br>"
      "<b>Toward point</b>: instead of 'direction', the move (pair) or sector (single vertex) that best points at "
      "'point'.<br>"
      "<b>Edge flip / collapse</b>: select the two ends of the edge (collapse keeps the lower index). <b>Vertex "
      "split</b>: select a vertex and two of its neighbours.<br>"
      "Impossible requests are refused with the reason (one irregular vertex cannot move alone, Theorem 5.1; a 5-7 "
      "pair cannot be cancelled, Theorem 5.5). A refused operation leaves the mesh unchanged. Afterwards vertices "
      "are recoloured and the resulting irregular vertices selected.";
  f.params = {
      Enum("operation", 0,
           {"5-7 pair move", "v5/v7 move with 5-7 pair generation",
            "v5/v7 move with 5-7 pair removal (triple cancellation)", "5-5-7-7 generation by flip",
            "5-5-7-7 generation by split", "5-5-7-7 removal", "Edge flip", "Edge collapse", "Vertex split",
            "5-5-7-7 generation by collapse and split"},
           "Operation", "Which atomic operation to apply to the selected vertices."),
      Int("direction", 0, 0, kMaxDirection, "Direction",
          "0..5. 5-7 pair move: the k-th move counter-clockwise from the v5-to-v7 edge. Single-vertex operations: "
          "the k-th 60-degree sector counter-clockwise from the reference edge (the selected neighbour; none: the "
          "projected +X axis)."),
      Enum("via", 0, {"Any", "Edge flip", "Edge collapse", "Vertex split"}, "Graph operation",
           "v5/v7 move with 5-7 pair generation: which graph operation makes the move (Any: the first that works, "
           "in the order flip, collapse, split)."),
      Enum("pairSide", 0, {"Any", "Counter-clockwise", "Clockwise"}, "Side of the new pair",
           "v5/v7 move with 5-7 pair generation: on which side of the move, seen from where the vertex was, the "
           "generated 5-7 pair lies (Any: counter-clockwise first)."),
      Bool("towardPoint", false, "Toward point",
           "Pair move, v5/v7 move and 5-5-7-7 generation: ignore 'direction' and go toward 'point'."),
      Point3("point", "Point",
             "Where to go: in the dialog, use Get / Surf. Pos. and double-click the mesh."),
      Bool("relax", true, "Relax after editing",
           "Local relaxation of the 2-ring around the changed vertices, projected onto the surface as it was before "
           "the filter (paper sec. 8)."),
      Colorize(),
  };
  f.apply = ApplyAtomic;
  c.push_back(f);

  f = FilterSpec();
  f.id = kRelax;
  f.name = "Irregular Vertices: Relax";
  f.pythonName = "apply_irregular_relaxation";
  f.classes = kSmoothing | kRemeshing;
  f.info =
      "Improves the shape of triangles without changing connectivity (Li et al., sec. 8). <b>Local</b>: vertices "
      "move one at a time in their tangent plane toward the centroid of their neighbours (Turk 1992). "
      "<b>Global</b>: solves the quadratic energy of eq. 5 (uniform edge lengths, equal angles around each vertex; "
      "the target length is each vertex's mean 1-ring edge length, not one global length, so adaptive sizing "
      "stays) with each vertex constrained to its tangent plane, with Eigen's conjugate gradient solver, then "
      "takes a guarded step: shortened, and triangles that would get worse sent back, so that the smallest angle "
      "never drops, the share of triangles under 30 degrees never rises and the energy strictly drops whenever "
      "anything moves; it stops when no such step is left. Moved vertices are projected back onto the mesh as it "
      "was before the filter; boundary vertices slide along the boundary as it was, corners (corner angle 30 "
      "degrees or more away from 180) stay. Vertices on sharp creases stay fixed. Logs and returns triangle "
      "quality (min_angle, mean_min_angle, percent_below_30, edge_length_spread, each _before and _after), the "
      "energy of eq. 5 over the relaxed region (energy_before, energy_after) and the Hausdorff distance to the "
      "input (hausdorff_percent).";
  f.params = {
      Enum("mode", 0, {"Local", "Global"}, "Mode",
           "Local: one vertex at a time (fast). Global: sparse least-squares solve of eq. 5."),
      Int("iterations", 10, 0, 100000, "Iterations", "Sweeps (local) or solve-and-project rounds (global)."),
      Enum("region", 0, {"All", "Selection", "Around irregular vertices"}, "Region",
           "Which vertices move. With nothing selected, Selection relaxes the whole mesh. Around irregular "
           "vertices: the 2-ring of every irregular vertex."),
      Bool("reproject", true, "Project onto the original surface",
           "Project moved vertices back onto the mesh as it was before the filter."),
      Float("featureAngle", 60, 0, 180, "Feature angle (degrees)",
            "Vertices on edges whose dihedral angle exceeds this stay fixed, so sharp creases survive. 0 disables."),
  };
  f.apply = ApplyRelax;
  c.push_back(f);

  f = FilterSpec();
  f.id = kReduce;
  f.name = "Irregular Vertices: Reduce to Valence 5 and 7";
  f.pythonName = "meshing_irregular_reduce_to_valence_5_and_7";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Type splitting (Li et al., sec. 6.3, fig. 9): every interior vertex of valence k > 7 becomes exactly k-6 v7, "
      "every v4 (v3) two (three) v5, so the other operations, which work on v5 and v7, apply. A vk is split into a "
      "chain of regular vertices with the v7s in two rows along its sides (k odd: the vertex itself stays a v7 at "
      "the chain's end); a v4 (v3) collapses one regular neighbour into itself and the two neighbours beside it (and, "
      "for a v3, the vertex itself) become the v5s. The first orientation that leaves every other irregular vertex "
      "unchanged is taken; when none does, one in which a neighbouring v5 (v7) becomes regular, cancelling with a "
      "produced v7 (v5). Vertices that cannot be reduced are kept and listed in the log. The v7s and v5s produced "
      "are selected.";
  f.params = {
      Enum("scope", 0, {"All irregular vertices", "Selected vertices"}, "Vertices",
           "Reduce every irregular vertex of valence other than 5 and 7, or only the selected ones."),
      RelaxAfterEditing(),
      Colorize(),
  };
  f.apply = ApplyReduce;
  c.push_back(f);

  f = FilterSpec();
  f.id = kAggregate;
  f.name = "Irregular Vertices: Aggregate";
  f.pythonName = "meshing_irregular_aggregation";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Type aggregation (sec. 6.3), the inverse of type splitting: the n selected v7s merge into one v(6+n) (v8, "
      "v9, v10, ...), two selected v5 into a v4 and three into a v3. v7s merge two or three at a time by edge "
      "collapses: two that face each other across an edge of regular vertices, or across an edge of the growing "
      "vertex, as Reduce to Valence 5 and 7 leaves them (two rows along a chain). Two v5 merge when a regular common "
      "neighbour has exactly one vertex between them, three when they are the corners of one triangle (a vertex "
      "split). No other vertex changes valence. Refused, with the reason, when the selection is not in such a "
      "configuration; two adjacent v5 cannot become a v4.";
  f.params = {RelaxAfterEditing(), Colorize()};
  f.apply = ApplyAggregate;
  c.push_back(f);

  f = FilterSpec();
  f.id = kMovePair;
  f.name = "Irregular Vertices: Move Pair";
  f.pythonName = "meshing_irregular_move_pair";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Moves the selected pair of irregular vertices (sec. 7.1). An adjacent 5-7 pair translates 'steps' steps: "
      "the first in 'direction' (0..5 counter-clockwise around the v5 from the v7), the next ones straight on; or, "
      "with 'toward point', toward the picked point until it gets no closer. A non-adjacent 5-7 pair, or a 5-5 or "
      "7-7 pair, moves by the pipeline of sec. 7.1.1: the lead vertex moves one step toward its neighbour "
      "'direction' (counted counter-clockwise from its neighbour of smallest index) and generates a 5-7 pair, "
      "which travels to the partner and cancels there, moving the partner: 5-5 and 7-7 pairs move symmetrically "
      "(sec. 7.1.2). A single irregular vertex cannot move alone (Theorem 5.1).";
  f.params = {
      Enum("lead", 0, {"Lower valence", "Higher valence", "Lower index", "Higher index"}, "Leading vertex",
           "Non-adjacent pairs: which selected vertex moves first (its partner follows)."),
      Int("direction", 0, 0, kMaxDirection, "Direction",
          "Adjacent 5-7 pair: 0..5 counter-clockwise around the v5 from the v7. Otherwise: neighbour index of the "
          "lead vertex, counted counter-clockwise from its neighbour of smallest index."),
      Int("steps", 1, 1, 1000000, "Steps", "How many steps the pair moves."),
      Bool("towardPoint", false, "Toward point",
           "Adjacent 5-7 pair: move toward 'point' until it gets no closer (steps and direction are ignored)."),
      Point3("point", "Point",
             "Where the pair should go: in the dialog, use Get / Surf. Pos. and double-click the mesh."),
      RelaxAfterEditing(),
      Colorize(),
  };
  f.apply = ApplyMovePair;
  c.push_back(f);

  f = FilterSpec();
  f.id = kCancelTriple;
  f.name = "Irregular Vertices: Cancel Triple";
  f.pythonName = "meshing_irregular_cancel_triple";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Triple cancellation (sec. 7.2): the selected 5-5-7 triple becomes one v5, a 5-7-7 triple one v7. An adjacent "
      "5-7 pair of the triple is moved to the third vertex, then the atomic removal applies. A 5-7 pair alone "
      "cannot be cancelled (Theorem 5.5).";
  f.params = {RelaxAfterEditing(), Colorize()};
  f.apply = ApplyCancelTriple;
  c.push_back(f);

  f = FilterSpec();
  f.id = kCancelQuadruple;
  f.name = "Irregular Vertices: Cancel Quadruple";
  f.pythonName = "meshing_irregular_cancel_quadruple";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Quadruple cancellation (sec. 7.3): the selected 5-5-7-7 quadruple, two adjacent 5-7 pairs, disappears: one "
      "pair is moved to the other until they annihilate. Refused when the two pairs cannot annihilate (they must be "
      "mirror images, sec. 7.3).";
  f.params = {RelaxAfterEditing(), Colorize()};
  f.apply = ApplyCancelQuadruple;
  c.push_back(f);

  f = FilterSpec();
  f.id = kGenerate;
  f.name = "Irregular Vertices: Generate";
  f.pythonName = "meshing_irregular_generate";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Generation (sec. 7.3), the inverse of cancellation: the selected v5 (v7) becomes a 5-5-7 (5-7-7) triple, or "
      "the selected regular vertex a 5-5-7-7 quadruple; the generated 5-7 pair is then moved 'spacing' steps away "
      "(each step strictly further away). A quadruple can instead be given its shape (fig. 11): the moved pair makes "
      "exactly 'side 1' steps in pair direction 'side 1 direction', then 'side 2' steps in 'side 2 direction', so "
      "the four vertices span a parallelogram whose opposite sides match and Cancel Quadruple can undo it.";
  f.params = {
      Enum("kind", 0, {"Triple from a v5 or v7", "Quadruple from a regular vertex"}, "Generate",
           "What the selected vertex becomes."),
      Int("direction", 0, 0, kMaxDirection, "Direction",
          "Neighbour index, counted counter-clockwise from the neighbour of smallest index."),
      Int("spacing", 2, 0, 100000, "Spacing", "Steps the generated 5-7 pair moves away (shape 'Move apart')."),
      Enum("shape", 0, {"Move apart", "Parallelogram (quadruple)"}, "Shape",
           "Move apart: the pair moves 'spacing' steps, each the one taking it furthest away. Parallelogram: a "
           "quadruple's pair moves exactly 'side 1' steps then 'side 2' steps along the pair directions given."),
      Int("side1Direction", 4, 0, 5, "Side 1 direction",
          "Parallelogram: pair direction of the first side (0..5 counter-clockwise around the v5 from the v7, as in "
          "'Atomic Operation')."),
      Int("side1", 3, 0, 100000, "Side 1", "Parallelogram: steps along the first side."),
      Int("side2Direction", 1, 0, 5, "Side 2 direction", "Parallelogram: pair direction of the second side."),
      Int("side2", 0, 0, 100000, "Side 2", "Parallelogram: steps along the second side."),
      RelaxAfterEditing(),
      Colorize(),
  };
  f.apply = ApplyGenerate;
  c.push_back(f);

  f = FilterSpec();
  f.id = kAutomaticReduction;
  f.name = "Irregular Vertices: Automatic Reduction";
  f.pythonName = "meshing_irregular_automatic_reduction";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Removes as many irregular vertices as the quality limits allow, with the paper's operations only (what its "
      "designers did by hand): type splitting into v5/v7 (sec. 6.3), triple and quadruple removals where they apply "
      "(sec. 6.2), 5-7 pairs moved to the nearest irregular vertex or gliding straight on until they cancel (sec. "
      "7.1-7.2), and stretched 5-7 pairs split into two adjacent pairs that are cancelled in turn; after that, a "
      "v5/v7 whose partner lies just beyond maxTravel (up to 1.5x it) gets one more try with twice the travel (far "
      "meetings). On a mesh with "
      "holes, interior irregular vertices near a hole are moved into its boundary or cancelled there, never leaving "
      "more boundary irregular vertices than the input had (corner rule); the boundary vertices around such an edit "
      "slide along the input's boundary. Every edit is "
      "relaxed locally and undone if it leaves a triangle under the minimum angle (beyond the angle allowance: a "
      "small share of the triangles may go down to the angle floor) or the input surface by more than "
      "the Hausdorff budget; the whole mesh is relaxed at the end. Creases stay sharp: the vertices of crease lines (8 "
      "or more connected edges sharper than 60 degrees that run as a line: all of their vertices but two, or "
      "but a tenth, continue straight, turning by under 30 degrees) are never relaxed, and an edit that moves the surface 0.05% "
      "of the diagonal away from an input crease is undone; as the triangles at a crease cannot be relaxed, they may "
      "have angles down to the minimum angle less 4 degrees. The budget bounds the result: it is measured at "
      "the end, and a run that overshoots is redone with stricter checks (at worst every edit is undone). Effort "
      "is bounded: around an irregular vertex where 20 edits (or maxTravel, if larger) were refused (typically a thin "
      "part), the run gives up, "
      "logs one line saying where and why, and tries there again only after an edit nearby was kept. "
      "Optionally remeshes isotropically first, and merges leftover pairs into v4 and v8 at the end (Aggregate "
      "leftovers). Deterministic. Logs and returns counts by valence, edits, triangle "
      "quality, Hausdorff distance and time.";
  f.params = {
      Percentage("remeshEdgeLength", 0, "Remesh first: target edge length",
                 "If > 0, the mesh is first remeshed isotropically to this edge length (vcglib's IsotropicRemeshing, "
                 "as 'Remeshing: Isotropic Explicit Remeshing'), so one run goes from a scan to a clean result. 0 "
                 "keeps the mesh as it is."),
      Int("targetCount", 0, 0, 1000000000, "Target irregular count",
          "Stop once this many interior irregular vertices remain (boundary irregular vertices do not count: "
          "the reduction never leaves more of them than the input had); 0 removes as many as the limits below allow. A closed surface of genus g keeps "
          "at least |12 - 12g| (Gauss-Bonnet, eq. 2)."),
      Float("hausdorffBudget", 0.5, 0, 100, "Hausdorff budget (% of diagonal)",
            "An edit whose triangles would leave the input surface by more than this (percent of the bounding-box "
            "diagonal) is undone."),
      Float("minAngle", 30, 0, 60, "Minimum angle (degrees)",
            "An edit is undone if, after local relaxation, a triangle around it has a smaller angle than this (unless "
            "one already had before). This keeps the irregular vertices the surface needs (v5 on tips, v7 in "
            "saddles)."),
      Float("angleAllowance", 0.8, 0, 100, "Angle allowance (% of triangles)",
            "Edits may leave up to this share of the mesh's triangles with an angle under the minimum angle, counted "
            "over the whole mesh (the input's own thin triangles included), as long as no angle falls under the "
            "angle floor; triangles at a crease line keep the minimum angle. A few thinner triangles let many more "
            "irregular vertices go (lion at 20K vertices: 79 interior irregular vertices left instead of 107, 0.4% of "
            "the triangles under 30 degrees). 0: every edit keeps the minimum angle."),
      Float("angleFloor", 20, 0, 60, "Angle floor (degrees)",
            "Within the angle allowance, no edit leaves a triangle with a smaller angle than this (nor than the "
            "minimum angle; unless one already had before)."),
      Int("maxTravel", 12, 1, 100000, "Pair travel (steps)",
          "How far a 5-7 pair moves toward another irregular vertex to cancel with it (straight glides go up to "
          "four times farther), in steps on a mesh of up to 20K vertices; on a finer mesh the same distance on the "
          "surface is more steps, and the travel grows with the square root of the vertex count (24 at 80K). Also "
          "the number of refused edits after which a region is given up, if above 20. 24 is the thorough setting: "
          "fewer irregular vertices left (bunny at 20K vertices: 38 instead of 62) for about 1.8 times the time."),
      Enum("protect", 0, {"Nothing", "Selected region untouched", "Selected irregular vertices kept"},
           "Protect the selection",
           "Selected region untouched: no edit changes a selected vertex or a face around one. Selected irregular "
           "vertices kept: they stay where they are with their valence."),
      Enum("relaxation", 0, {"Local", "Global"}, "Final relaxation",
           "After the edits the whole mesh is relaxed: local sweeps, or the global solve of eq. 5 followed by local "
           "sweeps (the global result is kept only if it does not lower the smallest angle). Every edit is relaxed "
           "locally as it is made."),
      Float("timeLimit", 60, 0, 1e7, "Time limit (seconds)",
            "Editing stops after this long; what was done is kept, relaxed and checked against the Hausdorff "
            "budget. 0: no limit (the result then does not depend on the machine's speed)."),
      Bool("aggregate", false, "Aggregate leftovers into v4/v8",
           "After the edits, two leftover v5 two edges apart (one regular vertex between them on a common "
           "neighbour) become one v4, and two v7 facing each other across an edge of two regular vertices become "
           "one v8 (type aggregation, sec. 6.3), where the minimum angle and the Hausdorff budget still hold. A "
           "leftover v5 (v7) with no such partner walks toward one of its type up to 16 edges away first (each step "
           "a move with 5-7 pair generation, the pair carried off to a cancellation), and the two merge if they get "
           "there. The curvature the surface needs stays, in fewer irregular vertices of higher valence. Off: the result keeps "
           "v5 and v7 only, as the paper's results do (a vertex whose split was refused keeps its valence)."),
      Colorize(),
  };
  f.apply = ApplyAutomaticReduction;
  c.push_back(f);

  f = FilterSpec();
  f.id = kBoundary;
  f.name = "Irregular Vertices: Boundary Operation";
  f.pythonName = "meshing_irregular_boundary_operation";
  f.classes = kRemeshing | kSelection;
  f.info =
      "Lets irregular vertices leave or enter the mesh through its boundary (eq. 2 counts boundary vertices too). "
      "A boundary vertex is regular at valence round(corner angle / 60) + 1: 4 on a smooth stretch, so a boundary "
      "vertex of valence 3 there counts as a v5 and one of valence 5 as a v7. Absorb into the boundary: select an "
      "interior v5 or v7 next to the boundary (a v5 leaves by splitting a boundary neighbour, a v7 by collapsing a "
      "boundary edge it faces; a boundary irregular vertex there is cancelled when possible), or the two vertices of "
      "a 5-7 pair next to the boundary. Move along the boundary: select a boundary vertex of valence 3 on a smooth "
      "stretch; it moves one vertex towards the chosen side. Generate a 5-7 pair from the boundary: select a regular "
      "boundary vertex (valence 4); one flip makes an interior 5-7 pair next to it and leaves a boundary 5-7 pair "
      "(valences 3 and 5). Move a boundary 5-7 pair along the boundary: select the two boundary vertices of a "
      "boundary pair (joined by a boundary edge, valences 3 and 5 on a smooth stretch); it moves 'steps' vertices "
      "towards its valence-3 or its valence-5 vertex (a step towards the 3 collapses the 3's interior neighbour into "
      "it, a step towards the 5 splits an ear off the 5), and where it meets a boundary irregular vertex or a "
      "boundary pair of opposite sign it cancels against it and stops. Generate two boundary 5-7 pairs: select a "
      "regular boundary vertex (valence 4); it goes inside and leaves a one-row bump, two boundary pairs of opposite "
      "sign, nothing irregular inside. All or nothing: a refused operation leaves the mesh unchanged and says why. The "
      "resulting irregular vertices are selected. Relax after editing: the 2-ring of the edit is relaxed; boundary "
      "vertices slide along the boundary as it was (corners, whose corner angle differs from 180 degrees by 30 or "
      "more, stay fixed).";
  f.params = {
      Enum("operation", 0,
           {"Absorb into the boundary", "Move along the boundary", "Generate a 5-7 pair from the boundary",
            "Move a boundary 5-7 pair along the boundary", "Generate two boundary 5-7 pairs"},
           "Operation", "What to do with the selected vertex (or pair)."),
      Enum("side", 0, {"First boundary neighbour", "Second boundary neighbour"}, "Side",
           "Move along / Generate a 5-7 pair: towards which boundary neighbour of the selected vertex. The first is "
           "the one whose boundary edge comes first going counter-clockwise around the vertex (seen from outside)."),
      Enum("pairDirection", 0, {"Towards its valence-3 vertex", "Towards its valence-5 vertex"}, "Boundary pair direction",
           "Move a boundary 5-7 pair: the way along the boundary, named by the pair's own vertices."),
      Int("steps", 1, 1, 100000, "Steps",
          "Move a boundary 5-7 pair: how many boundary vertices it moves (fewer if it cancels on the way)."),
      RelaxAfterEditing(),
      Colorize(),
  };
  f.apply = ApplyBoundary;
  c.push_back(f);

  f = FilterSpec();
  f.id = kPattern;
  f.name = "Irregular Vertices: Pattern";
  f.pythonName = "compute_color_irregular_pattern";
  f.classes = kFaceColoring | kQuality | kMeasure;
  f.changesConnectivity = false;
  f.info =
      "The paper's application (Li et al., sec. 9-10, Figs. 1, 12-14): a pattern made from the triangulation's own "
      "edges, shown as face colours (a hue per kind of region, shades per region; conflicts magenta) with the "
      "region id in face quality, and the measures a designer compares before and after editing the irregular "
      "vertices.<br>"
      "<b>Stripes</b> (Fig. 1): triangle strips between consecutive straight edge lines of one lattice direction. "
      "The direction is one edge of the seed face (the selected face, else a face of the selected vertex, else face "
      "0) and is carried from face to face: an edge line goes straight through a vertex of valence 6 (the opposite "
      "edge). Around a v5 or v7 the direction comes back turned by 60 degrees: the faces where it disagrees are "
      "<i>conflict</i> (degenerate) regions. A line that stops at an interior irregular vertex does not separate "
      "strips, so the two rows beside it make one strip of width two (three where two lines stop, ...). Strips "
      "alternate between two colours (every 'period' strips).<br>"
      "<b>Zebra</b> (Fig. 13): the same strips, but the direction follows the lattice through the singularities: "
      "the seams where it comes back turned are placed at the irregular vertices (on paths joining them to the "
      "boundary or to each other; a 5-7 pair's on its own edge), the strips just turn there, and nothing is a "
      "conflict.<br>"
      "Both report the hexagonal cells of the lattice: the one-rings of every third vertex (a 3-colouring carried "
      "from the seed face, whose vertex opposite the direction edge is a centre); a cell has as many sides as its "
      "centre's valence (a v5 centre: a pentagon).<br>"
      "<b>Stars</b> (Fig. 12): stars around the selected vertices, else every interior v5; reports the seeds with no "
      "other irregular vertex within the radius. <b>Circles</b> (Fig. 14): rings of faces; generate many irregular "
      "vertices first (Irregular Vertices: Generate), then pattern.<br>"
      "<b>Panels</b>: optionally every region becomes a panel (inset, extruded polygon) in a new layer 'panels', "
      "ready to export. The mesh's geometry and connectivity are never changed. Returns (pymeshlab dict): strips, "
      "strip_width_1, strip_width_2, strip_width_3_or_more, strip_width_histogram, cells, non_hexagonal_cells, "
      "cell_sides_histogram, conflict_regions, conflict_faces, star_seeds, isolated_star_seeds, circles, panels, "
      "panel_sides_histogram, regions, seed_face. Refuses non-manifold or polygonal meshes without changing them.";
  f.params = {
      Enum("pattern", 0, {"Stripes", "Zebra", "Stars", "Circles"}, "Pattern", "Which pattern to make."),
      Int("direction", 0, 0, 2, "Direction",
          "Stripes and zebra: which edge of the seed face (0, 1, 2: the edge from its vertex k to vertex k+1) gives "
          "the strips' lattice direction. The three values give the three families of lines."),
      Int("period", 2, 1, 1000, "Period",
          "Stripes and zebra: strips alternate between the two colours every 'period' strips (2: A B A B)."),
      Int("starRadius", 3, 1, 1000, "Star radius", "Stars: the star's radius in rings of edges around its seed."),
      Int("ringWidth", 1, 1, 1000, "Circle ring width", "Circles: rings of faces per circle band."),
      Bool("panels", false, "Panels",
           "Also write a new layer 'panels' in which every region is an inset, extruded panel (geometry replacement, "
           "Fig. 1 middle and right)."),
      Float("panelInset", 0.15, 0.0, 0.25, "Panel inset",
            "Panels: inset of each panel's outline, as a fraction of the mean edge length (at most 0.25: from about "
            "0.28 on, the outline of a one-triangle region folds)."),
      Float("panelExtrusion", 0.25, -10.0, 10.0, "Panel extrusion",
            "Panels: extrusion along the normal, as a fraction of the mean edge length (0: flat)."),
  };
  f.apply = ApplyPattern;
  c.push_back(f);
  return c;
}

}  // namespace

const std::vector<FilterSpec>& Catalog() {
  static const std::vector<FilterSpec> catalog = MakeCatalog();
  return catalog;
}

}  // namespace filter_irregular
