#include "cli/map_args.hpp"

#include "generators/boundary_shapes.hpp"
#include "cli/command_line.hpp"
#include "cli/common_options.hpp"
#include "cli/option_values.hpp"
#include "io/read_facets.hpp"
#include "kernel/coordinate_arith.hpp"

namespace cmx::cli {
namespace {

const HelpText help = {
    "usage: cmx map DOMAIN (--boundary B.txt | --codomain MESH | --shape SHAPE) [-o OUT]\n"
    "               [--format tmap,vtu,ovm,vtk,mesh,msh] [--report R.json] [--report-on-failure]\n"
    "               [--time-limit S] [--check] [--no-collapse] [--no-merge] [--no-flip-collapse]\n"
    "               [--order priority|index|strict-index|random:SEED] [--seed N] [--corners "
    "random|farthest]\n"
    "               [--precision dyadic|shift|segment|none]\n"
    "               [--filter cascade|interval|exact|mpfr:BITS] [--lp certified|exact|glpk] [--norm "
    "l2-upper|l1]\n"
    "               [--snap repair|chebyshev-pass|nearest|none] [--trace T.csv] [--smooth N]\n"
    "               [--arith rational|double|mpfr:BITS] [--no-collapse-refinement] [--shelled MODE] "
    "[--subclusters N]\n"
    "               [--combinatorial] [--quiet] [--version]\n",
    "Maps the ball-topology tet mesh DOMAIN bijectively onto the star-shaped domain bounded by the\n"
    "prescribed boundary positions (Cluster-Mesh Expansion), verifies the result exactly and prints\n"
    "the verdict. Options take their value as --opt VALUE or --opt=VALUE.\n",
    "Exit codes: 0 mapped and verified; 2 bad command line (also: an output path that is an input);\n"
    "3 unreadable or malformed input; 4 not a valid problem (not a ball, inverted or flat tets in DOMAIN,\n"
    "boundary mismatch, degenerate or mirrored boundary); 5 boundary not star-shaped; 6 time limit;\n"
    "7 stuck; 8 precision lost (--arith double|mpfr:BITS); 9 an output file cannot be written (checked\n"
    "before computing); 10 internal error (please report).\n"
    "On any failure no map is written (an existing file is left untouched). The report and the trace of\n"
    "a failed run are written only to paths that do not exist yet, unless --report-on-failure.\n"
    "Stuck on a NOBUENOSS (no cluster vertex satisfies Eq. (1)), the run then searches for a shelling\n"
    "of the input (8 greedy attempts), which the paper's fallback needs, and says whether it found one.\n"
    "When one is found, the run starts again and replays it (paper Alg. 2) until greedy expansion can\n"
    "take over (--replay-shelling after-nobuenoss); each plan that ends stuck is replayed once more\n"
    "with --shelled after-pushes before the next. Otherwise, or when every replay fails, it ends as\n"
    "stuck (exit 7) with the reasons. On large inputs the replay's refinement can run away.\n"};

std::string one_of(const std::string& what, const std::string& text, const std::string& choices) {
  return "unknown " + what + " '" + text + "' (" + choices + ")";
}

// The parser of an option that takes one of a name table's values (algorithm/option_names.hpp):
// the value, or an error that lists the choices.
template <class Parse>
auto one_of_table(const char* what, Parse parse, const char* choices) {
  return [=](const std::string& text) {
    const auto value = parse(text);
    if (!value) throw std::invalid_argument(one_of(what, text, choices));
    return *value;
  };
}

void add_problem_options(CLI::App& app, MapArgs& a) {
  app.add_option("DOMAIN", a.domain, "the mesh to map: .ovm .vtk .vtu .mesh .msh .node/.ele, or a facet\nlist .facets (then --combinatorial is implied)")
      ->required()
      ->type_name("");
  app.add_flag("--combinatorial", a.options.combinatorial,
               "DOMAIN is a ball given by its tets alone (a facet list, or a mesh\n"
               "whose positions are ignored): the tets are oriented alike, the result\n"
               "realises a subdivision of the complex in the target (every tet\n"
               "positive, boundary as prescribed, checked exactly, and checked to\n"
               "subdivide the complex); the .tmap's source columns are the target;\n"
               "no collapses, init shrink; --shape works from the combinatorics");
  app.add_option("--boundary", a.boundary, "lines 'index x y z' (exact numbers) for exactly the boundary\nvertices")
      ->type_name("B.txt");
  app.add_option("--codomain", a.codomain, "a mesh with DOMAIN's connectivity whose boundary vertices give\nthe positions")
      ->type_name("MESH");
  const auto shape = [](const std::string& text) {
    if (!generators::parse_boundary_shape(text))
      throw std::invalid_argument(one_of("shape", text, "tet, stiff-tet, sphere, star[:SEED]"));
    return text;
  };
  add_parsed(app, "--shape", a.shape, shape, "generated boundary: tet, stiff-tet, sphere, star[:SEED]")->type_name("SHAPE");
  add_parsed(app, "--seed", a.seed, parse_seed, "seed of generated shapes (default 1234; star:SEED names its own);\n0 to 2^64-1")->type_name("N");
  add_corners_option(app, a.corners);
}

void add_output_options(CLI::App& app, MapArgs& a) {
  app.add_option("-o,--output", a.out,
                 "output path; OUT's extension (if one of the formats) selects that\n"
                 "format, otherwise OUT is a stem. The exact map OUT.tmap is always\n"
                 "written. No output may be one of the input files (exit 2).")
      ->type_name("OUT");
  auto formats = app.add_option_function<std::vector<std::string>>(
      "--format",
      [&a](const std::vector<std::string>& lists) {
        for (const auto& list : lists)
          try {
            for (auto& f : parse_list(list, map_formats(), "format")) a.formats.push_back(std::move(f));
          } catch (const std::invalid_argument& e) {
            throw CLI::ValidationError("--format", e.what());
          }
      },
      "more formats, comma-separated: tmap, vtu, ovm, vtk, mesh, msh (Gmsh\n"
      "4.1 ASCII). Display formats carry the doubles chosen by --snap (the\n"
      "report says whether they are valid); vtu, vtk and msh also carry\n"
      "the source positions as point data 'source' and per tet 'added' (it\n"
      "has a vertex added by refinement), 'source_volume', 'target_volume'\n"
      "and 'min_dihedral_deg' (in the target). May be given more than once");
  formats->type_name("LIST")->allow_extra_args(false)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--report", a.report, "statistics and verdicts as JSON (written atomically)")->type_name("R.json");
  app.add_flag("--report-on-failure", a.report_on_failure,
               "write the report and the trace of a failed run even over existing\n"
               "files (by default they are written only where no file exists yet)");
  app.add_option("--trace", a.trace,
                 "one CSV row per expansion (kind, cone size, LP outcome, bits of the\n"
                 "new position, largest and mean bits so far, added vertices,\n"
                 "degenerate tets and cluster vertices left, seconds); written also\n"
                 "when the run stops early; draw it with `cmx plot T.csv -o T.svg`.\n"
                 "Slows the run down.")
      ->type_name("T.csv");
}

void add_run_options(CLI::App& app, MapArgs& a) {
  add_parsed(app, "--time-limit", a.options.time_limit_seconds, parse_time_limit,
             "stop the expansion after S seconds (exit 6); once the exact map is\n"
             "complete, the double output stops at the limit too (the map is still\n"
             "written). S > 0; inf (or a number beyond the doubles) is no limit,\n"
             "which the report gives as time_limit 0, as without the option")
      ->type_name("S");
  app.add_flag("--check", a.options.check, "assert every invariant after every step (slow; for testing)");
  app.add_flag("--no-collapse", [&a](std::int64_t) { a.options.collapse = false; },
               "keep every added vertex (by default added vertices are collapsed away\n"
               "at the end wherever the map stays valid)");
  app.add_flag("--no-merge", [&a](std::int64_t) { a.options.merge = false; },
               "collapse added vertices only where the vertex kept can stay in place\n"
               "(by default an added vertex is also merged into an interior neighbour\n"
               "that moves into its new star's kernel: in source and target if it was\n"
               "added too, in the target only if it is an input vertex; or collapsed\n"
               "into a neighbour that stays while up to three other added vertices\n"
               "move, or after flips of its star that keep every tet positive)");
  app.add_flag("--no-flip-collapse", [&a](std::int64_t) { a.options.flip_collapse = false; },
               "merges as above but without the flips (faster on inputs without\n"
               "interior vertices, which then keep more added vertices)");
  app.add_flag("--no-collapse-refinement", [&a](std::int64_t) { a.options.collapse_refinement = false; },
               "do not collapse, right after each star-shapification, the vertices it\n"
               "added (by default they are collapsed wherever every invariant\n"
               "survives: paper Sec. 4.2.2)");
  const auto shelled = one_of_table("shelled mode", algorithm::parse_shelled_mode, "when-stuck, after-pushes, first");
  add_parsed(app, "--shelled", a.options.shelled, shelled,
             "when to star-shapify by shelling the cone base onto its witness's\n"
             "star (default when-stuck: the fallback, once every candidate has failed\n"
             "everything else); after-pushes: wherever bends and pushes failed;\n"
             "first: before bends and pushes (these two are for tests and comparisons)")
      ->type_name("MODE");
  const auto replay =
      one_of_table("replay mode", algorithm::parse_replay_mode, "off, after-nobuenoss, until-greedy, full");
  add_parsed(app, "--replay-shelling", a.options.replay, replay,
             "replay a shelling of the input from the start (paper Sec. 4.3, Alg. 2):\n"
             "after-nobuenoss (default: when greedy expansion ends in a NOBUENOSS\n"
             "and a shelling is found, the run again with until-greedy); off (never);\n"
             "until-greedy, from the start until topological expansion of the cluster\n"
             "left completes in the run's order and in it without its deferral, then\n"
             "the greedy loop in the latter (of 8 shellings, the one whose plan gets\n"
             "there soonest; the next, up to 4, when one runs away or the greedy loop\n"
             "after it ends stuck); full, every step (of the first shelling found).\n"
             "Splits of the plan wait until it needs them; a plan that meets a step it\n"
             "cannot make is planned again from there, up to 4 times")
      ->type_name("MODE");
}

// --init and --threads: where the target starts, and how many stars (or attempts) run at once.
void add_local_options(CLI::App& app, MapArgs& a) {
  const auto init = [&a](const std::string& text) {
    if (const auto kind = algorithm::parse_initial_map_kind(text); kind && *kind != algorithm::InitialMapKind::given)
      return *kind;
    if (text == "codomain") return algorithm::InitialMapKind::given;
    if (text.empty() || text == "given") throw std::invalid_argument(one_of("initial map", text, "auto, shrink, tutte, codomain, FILE"));
    a.init_file = text;
    return algorithm::InitialMapKind::given;
  };
  add_parsed(app, "--init", a.options.init, init,
             "initial map (default auto): shrink = every interior vertex at the\n"
             "shrink point, the whole cluster expanded (paper Alg. 1); tutte = a 3D\n"
             "Tutte map whose non-positive tets are enclosed in stars, each star\n"
             "mapped as a problem of its own by the shrink method, the rest kept;\n"
             "codomain = the same from the --codomain mesh's interior positions;\n"
             "FILE = from lines 'index x y z' for every vertex; auto = tutte, or\n"
             "shrink when more than 5 % of the Tutte map's tets are inverted or\n"
             "flat in doubles (a system costly to factorise is solved approximately\n"
             "first and given up above 10 %) or its stars would hold more than half\n"
             "of the tets, and after it when the stars' stitched doubles are not\n"
             "valid (the global map is then kept if its doubles are; the report's\n"
             "'local' says which ran and why; --snap repair's last stage follows\n"
             "every init). A file named like a keyword: ./auto")
      ->type_name("INIT");
  add_parsed(
      app, "--threads", a.options.threads, [](const std::string& t) { return parse_integer(t, 0, 1024); },
      "stars mapped at once, greedy shelling attempts after a NOBUENOSS, the\n"
      "replay's plans ranked and its attempts after it (each plan in each\n"
      "--shelled mode), and --shape's corner attempts (default 0: the\n"
      "machine's cores); the output is the same for every count")
      ->type_name("N");
}

void add_expansion_options(CLI::App& app, MapArgs& a) {
  add_parsed(app, "--subclusters", a.options.subclusters, [](const std::string& t) { return parse_integer(t, 0, 4); },
             "when no single vertex is simply expandable, try expanding N = 2..4\n"
             "cluster vertices together before refining (paper Sec. 4.2.5;\n"
             "default 4; 0 or 1: off)")
      ->type_name("N");
  add_parsed(app, "--smooth", a.options.smooth_every, [](const std::string& t) { return parse_integer(t, 0, 1000000); },
             "every N expansions, move the cluster's expanded neighbours near the\n"
             "last expansions toward their neighbours' centroid where every tet\n"
             "keeps its state (paper Sec. 4.2.4; default 0: off; at most 1000000)")
      ->type_name("N");
  add_order_option(app, a.options.order,
                   "expansion order: priority (default: paper Sec. 4.1.2), index (the\n"
                   "class first, then the lowest id), random:SEED, strict-index (the\n"
                   "lowest id first, refined if need be: the order of cmx topo-expand\n"
                   "--order index, for experiments; it forces refinement where the\n"
                   "others would expand simply and is much slower); any of them followed\n"
                   "by ',defer:A-B' (for experiments; --init shrink or --combinatorial\n"
                   "only) expands the input's vertex ids A to B-1 only when no other\n"
                   "candidate is queued, a refined one included (one whose refinement\n"
                   "failed waits for its star to change)");
  const auto precision =
      one_of_table("precision policy", algorithm::parse_precision_policy, "dyadic, shift, segment, none");
  add_parsed(app, "--precision", a.options.placement.precision, precision,
             "precision reduction of new positions (default dyadic)")
      ->type_name("P");
}

void add_arithmetic_options(CLI::App& app, MapArgs& a) {
  add_filter_option(app, a.options.filter, false, "predicate arithmetic: cascade (default), interval, exact,\nmpfr:BITS (all exact)");
  add_lp_option(app, a.options.placement.lp.backend, "LP backend: certified (default), exact, glpk (if built)");
  add_norm_option(app, a.options.placement.lp.norm, "Chebyshev row weights: l2-upper (default), l1");
  const auto snap = one_of_table("snap policy", algorithm::parse_snap_policy, "repair, chebyshev-pass, nearest, none");
  add_parsed(app, "--snap", a.options.snap, snap,
             "double output (default repair): repair = the nearest doubles if they\n"
             "are valid, else chebyshev-pass, then open the crowds of vertices\n"
             "around the shrink point (exact), then re-centre the vertices of tets\n"
             "the doubles invert among their neighbours' doubles; a boundary vertex\n"
             "of an all-boundary tet that rounding breaks may take another double\n"
             "within 1 ulp; last, when they are still not valid, the map is mapped\n"
             "again from its own nearest doubles by local repair, kept if its\n"
             "doubles are valid;\n"
             "chebyshev-pass = move every interior vertex to the\n"
             "Chebyshev centre of its star (exact map stays valid), then round;\n"
             "nearest = round and check; none = round, no check")
      ->type_name("POLICY");
  const auto arith = [](const std::string& text) {
    std::string why;
    const auto c = parse_coordinate_arith(text, &why);
    if (!c) throw std::invalid_argument(why);
    return *c;
  };
  add_parsed(app, "--arith", a.options.placement.arith, arith,
             "coordinate arithmetic (default rational: exact). double or mpfr:BITS\n"
             "(2..65536 significant bits) round the input on entry (the report\n"
             "counts what moved) and every coordinate the method creates;\n"
             "predicates stay exact on the rounded values. Such a run stops where\n"
             "rounding first makes a tet inverted or degenerate (exit 8) and\n"
             "reports the step, vertex and tet; --snap is then nearest")
      ->type_name("A");
}

}  // namespace

const std::vector<std::string>& map_formats() {
  static const std::vector<std::string> formats = {"tmap", "vtu", "ovm", "vtk", "mesh", "msh"};
  return formats;
}

std::optional<int> parse_map_args(const std::vector<std::string>& args, MapArgs& a) {
  CommandLine line("map", help);
  CLI::App& app = line.app();
  line.quiet_flag()->description("no progress line, no verdict on stdout (errors stay)");
  add_problem_options(app, a);
  add_output_options(app, a);
  add_run_options(app, a);
  add_local_options(app, a);
  add_expansion_options(app, a);
  add_arithmetic_options(app, a);
  if (const auto done = line.parse(args)) return done;
  if (io::is_facet_list_path(a.domain)) a.options.combinatorial = true;
  if (!a.boundary.empty() + !a.codomain.empty() + !a.shape.empty() != 1)
    usage_error("give exactly one of --boundary, --codomain, --shape");
  if (app.get_option("--corners")->count() > 0 && a.shape.empty())
    usage_error("--corners chooses the corners of a generated boundary: it needs --shape");
  if (app.get_option("--seed")->count() > 0 && a.shape.empty())
    usage_error("--seed chooses a generated boundary: it needs --shape");
  if (a.options.init == algorithm::InitialMapKind::given && a.init_file.empty() && a.codomain.empty())
    usage_error("--init codomain needs --codomain");
  return std::nullopt;
}

}  // namespace cmx::cli
