// ergo_validate: a simulated contact-pressure map against a measured one (paper §6). The
// scene is posed as for ergo_optimize (--flagfile=data/shoe.flags, a --preset, a user's body
// or a designed --support_mesh) and solved once with the body placed afresh; its pressures
// seen along y are compared with
//   --sensors=FILE  point sensors (ergo/ergonomics/sensor_readings.h): trimmed means,
//                   reference normalisation α_i r_i = C, linearly precise biharmonic
//                   interpolation onto the support's top, C set for the load; or
//   --plate=FILE    a pressure plate's export (ergo/ergonomics/pressure_plate_csv.h).
// The measured map is aligned to the simulated one by a rigid motion of the plane, then
// compared: region shares along the footprint's axis, peaks, Pearson correlation, footprint
// overlap, total force. Writes OUT/comparison.json, comparison.md, maps.json, comparison.png
// (tools/plot_validation.py) and, for sensors, sensors.csv, as one unit.
// --write_synthetic_plate=FILE / --write_synthetic_sensors=FILE instead write what a plate or
// sensors would measure of the simulated map (a known motion applied to the plate), for
// round trips and trials.
// Exit status: 0 compared (or synthetic file written), 1 the equilibrium did not succeed
// (nothing written), 2 unusable input, 130 / 143 interrupted (nothing written).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <omp.h>

#include "ergo/ergonomics/pressure_map_alignment.h"
#include "ergo/ergonomics/pressure_map_comparison.h"
#include "ergo/ergonomics/pressure_plate_csv.h"
#include "ergo/ergonomics/sensor_pressure_map.h"
#include "ergo/ergonomics/sensor_readings.h"
#include "ergo/ergonomics/support_top_surface.h"
#include "ergo/ergonomics/synthetic_measurements.h"
#include "ergo/ergonomics/trimmed_statistics.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"
#include "ergo/mesh/text_reader.h"
#include "tools/common/child_process.h"
#include "tools/common/flag_checks.h"
#include "tools/common/output_directory.h"
#include "tools/common/run_signals.h"
#include "tools/ergo_validate/simulated_contact.h"
#include "tools/ergo_validate/validation_report.h"

DEFINE_string(sensors, "",
              "point-sensor readings, CSV: sensor,x_mm,z_mm,value[,reference], one row per "
              "sample (ergo/ergonomics/README.md)");
DEFINE_string(plate, "",
              "a pressure plate's export, CSV: the matrix of cell pressures with '# pitch_mm=' "
              "and '# unit=' lines (ergo/ergonomics/README.md)");
DEFINE_string(out, "", "output directory (required to compare; replaced as a whole)");
DEFINE_string(trim, "50/600",
              "sensors: samples dropped at each end before the mean: a count (50), a fraction "
              "below 0.5 (0.0833) or K/N (50/600, the paper's 50 lowest and highest of 600)");
DEFINE_double(load_n, 0,
              "sensors: the total force the map is scaled to, N; 0 = the scene's load (body "
              "weight and external force)");
DEFINE_double(plate_pitch, 0, "plate: cell pitch in mm, overriding the file's '# pitch_mm='");
DEFINE_string(plate_unit, "",
              "plate: unit of the cells (Pa, kPa, MPa, N/cm2, mmHg, psi), overriding the file's "
              "'# unit=' (default kPa)");
DEFINE_bool(plate_to_load, false,
            "plate: scale the plate so its total force is the load (plates often read low); "
            "false compares the forces as measured");
DEFINE_string(align, "auto",
              "how the measured map may move onto the simulated one: rigid (rotation and "
              "shift), translation, or none; auto = rigid for a plate (its own frame), none for "
              "sensors (measured on the support, in its frame)");
DEFINE_string(align_by, "footprint",
              "alignment score: footprint (overlap of where the pressure exceeds the footprint "
              "threshold) or pressure (cosine similarity of the pressures)");
DEFINE_string(regions, "auto",
              "regions along the footprint's principal axis as NAME:END fractions, e.g. "
              "rearfoot:0.3333,midfoot:0.6667,forefoot:1; auto = those thirds for the shoe, "
              "first_third,middle_third,last_third otherwise");
DEFINE_string(region_axis, "+z",
              "the footprint's axis points towards this end (fraction 1): +x, -x, +z or -z "
              "(the shoe: +z, heel to toes)");
DEFINE_double(footprint_fraction, 0.02,
              "footprints: where the pressure exceeds this fraction of the simulated peak");
DEFINE_double(grid_pitch_mm, 2, "grid on which the fields are aligned and compared, mm");
DEFINE_string(simulated_side, "skin",
              "simulated map: skin (the forces the solver applied; they sum to the load) or "
              "support (the support-side samples of the score)");
DEFINE_bool(plot, true,
            "write comparison.png with tools/plot_validation.py (python3 + matplotlib)");
DEFINE_int32(threads, 0, "threads for the equilibrium (0 = all cores)");
DEFINE_string(write_synthetic_plate, "",
              "instead of comparing: write this CSV, what a plate would read of the simulated "
              "map (--synthetic_* flags)");
DEFINE_string(write_synthetic_sensors, "",
              "instead of comparing: write this CSV, what point sensors and a reference would "
              "read of the simulated map (--synthetic_* flags)");
DEFINE_double(synthetic_rotation_deg, 0,
              "synthetic plate: the map's rotation on the plate, degrees");
DEFINE_string(synthetic_shift_mm, "0,0", "synthetic plate: the map's shift on the plate DX,DZ, mm");
DEFINE_double(synthetic_pitch_mm, 5, "synthetic plate: cell pitch, mm");
DEFINE_double(synthetic_plate_noise, 0.02,
              "synthetic plate: Gaussian noise on loaded cells, as a fraction of the peak");
DEFINE_double(synthetic_sensor_pitch_mm, 15, "synthetic sensors: spacing of the locations, mm");
DEFINE_int32(synthetic_samples, 600, "synthetic sensors: samples per location");
DEFINE_double(synthetic_sensor_noise, 0.05, "synthetic sensors: relative noise per sample");
DEFINE_double(synthetic_posture, 0.1,
              "synthetic sensors: spread of the posture factor between locations (relative)");
DEFINE_double(synthetic_outliers, 0.04, "synthetic sensors: share of spiked samples");
DEFINE_int32(synthetic_seed, 1, "synthetic measurements: random seed");
DECLARE_string(scenario);

namespace ergo {
namespace {

constexpr double kDegree = M_PI / 180;

Eigen::Vector2d ParseShift(const std::string& text) {
  const std::vector<std::string> items = SplitList(text, ',');
  Eigen::Vector2d shift;
  bool ok = items.size() == 2;
  for (size_t k = 0; ok && k < 2; ++k)
    ok = ParseDouble(items[k], &shift[static_cast<Eigen::Index>(k)]) &&
         std::isfinite(shift[static_cast<Eigen::Index>(k)]);
  RequireFlag(ok, "synthetic_shift_mm", "'" + text + "' is not two finite numbers",
              "write DX,DZ in mm, e.g. 12,-7");
  return 1e-3 * shift;
}

struct RunFlags {
  SampleTrim trim;
  std::vector<PressureRegion> regions;
  Eigen::Vector2d region_axis;
  AlignmentMode align = AlignmentMode::kRigid;
  AlignmentScore align_by = AlignmentScore::kFootprint;
  SimulatedSide side = SimulatedSide::kSkin;
};

// Every flag of this tool, checked before any work (the scene's are checked where read).
RunFlags ValidateRunFlags() {
  RunFlags flags;
  const bool synthetic =
      !FLAGS_write_synthetic_plate.empty() || !FLAGS_write_synthetic_sensors.empty();
  if (synthetic) {
    RequireFlag(
        FLAGS_sensors.empty() && FLAGS_plate.empty(),
        FLAGS_write_synthetic_plate.empty() ? "write_synthetic_sensors" : "write_synthetic_plate",
        "writes a synthetic measurement and compares nothing, but --sensors or --plate is given",
        "run once to write the file, then again with --sensors or --plate to compare");
  } else {
    RequireFlag(
        FLAGS_sensors.empty() != FLAGS_plate.empty(), "sensors",
        FLAGS_sensors.empty() ? "and --plate are both missing" : "and --plate are both given",
        "give the measurement to compare: --sensors=readings.csv or --plate=export.csv");
    RequireFlag(!FLAGS_out.empty(), "out", "is required",
                "name the output directory, e.g. --out=validation");
  }
  std::string error;
  if (!ParseSampleTrim(FLAGS_trim, &flags.trim, &error)) throw InputError("--trim", "", error, "");
  RequireInRange("load_n", FLAGS_load_n, 0, 1e6, "newtons; 0 = the scene's load");
  RequireInRange("plate_pitch", FLAGS_plate_pitch, 0, 1000,
                 "millimetres, e.g. 5.08; 0 = the file's");
  double pascals = 0;
  RequireFlag(FLAGS_plate_unit.empty() || PascalsPerUnit(FLAGS_plate_unit, &pascals), "plate_unit",
              "'" + FLAGS_plate_unit + "' is not a pressure unit ergo reads",
              "use one of " + PressureUnitNames());
  // auto: a plate's export lies in the plate's frame and must be placed; sensors are located
  // on the support itself, and an interpolated map's soft outline is a poor handle for a fit
  // (on the quick shoe's synthetic sensors a rigid fit moved it 0.9° and 1.5 mm off and
  // lowered Pearson from 0.976 to 0.960).
  const std::string align =
      FLAGS_align != "auto" ? FLAGS_align : (FLAGS_plate.empty() ? "none" : "rigid");
  RequireFlag(ParseAlignmentMode(align, &flags.align), "align", "'" + FLAGS_align + "' is unknown",
              "use auto, rigid, translation or none");
  RequireFlag(ParseAlignmentScore(FLAGS_align_by, &flags.align_by), "align_by",
              "'" + FLAGS_align_by + "' is unknown", "use footprint or pressure");
  RequireFlag(ParseSimulatedSide(FLAGS_simulated_side, &flags.side), "simulated_side",
              "'" + FLAGS_simulated_side + "' is unknown", "use skin or support");
  const std::string regions = FLAGS_regions != "auto" ? FLAGS_regions
                              : FLAGS_scenario == "shoe"
                                  ? "rearfoot:0.3333,midfoot:0.6667,forefoot:1"
                                  : "first_third:0.3333,middle_third:0.6667,last_third:1";
  if (!ParsePressureRegions(regions, &flags.regions, &error))
    throw InputError("--regions", "", error, "");
  const std::map<std::string, Eigen::Vector2d> axes = {
      {"+x", {1, 0}}, {"-x", {-1, 0}}, {"+z", {0, 1}}, {"-z", {0, -1}}};
  RequireFlag(axes.count(FLAGS_region_axis) == 1, "region_axis",
              "'" + FLAGS_region_axis + "' is unknown", "use +x, -x, +z or -z");
  flags.region_axis = axes.at(FLAGS_region_axis);
  RequireInRange("footprint_fraction", FLAGS_footprint_fraction, 1e-4, 0.5,
                 "a fraction of the simulated peak, e.g. 0.02");
  RequireInRange("grid_pitch_mm", FLAGS_grid_pitch_mm, 0.2, 20, "millimetres, e.g. 2");
  RequireInRange("threads", static_cast<long>(FLAGS_threads), 0, 1024, "0 = all cores");
  RequireInRange("synthetic_rotation_deg", FLAGS_synthetic_rotation_deg, -360, 360,
                 "degrees, e.g. 8");
  ParseShift(FLAGS_synthetic_shift_mm);
  RequireInRange("synthetic_pitch_mm", FLAGS_synthetic_pitch_mm, 0.5, 50, "millimetres, e.g. 5");
  RequireInRange("synthetic_plate_noise", FLAGS_synthetic_plate_noise, 0, 1,
                 "a fraction of the peak, e.g. 0.02");
  RequireInRange("synthetic_sensor_pitch_mm", FLAGS_synthetic_sensor_pitch_mm, 2, 200,
                 "millimetres, e.g. 15");
  RequireInRange("synthetic_samples", static_cast<long>(FLAGS_synthetic_samples), 1, 20000,
                 "e.g. 600");
  RequireInRange("synthetic_sensor_noise", FLAGS_synthetic_sensor_noise, 0, 1,
                 "relative, e.g. 0.05");
  RequireInRange("synthetic_posture", FLAGS_synthetic_posture, 0, 0.5, "relative, e.g. 0.1");
  RequireInRange("synthetic_outliers", FLAGS_synthetic_outliers, 0, 0.5,
                 "a share of samples, e.g. 0.04");
  RequireInRange("synthetic_seed", static_cast<long>(FLAGS_synthetic_seed), 0, 2147483647L,
                 "e.g. 1");
  return flags;
}

// The scene's equilibrium and its simulated map; nullopt (with the reason on stderr) when it
// did not succeed or was interrupted.
struct Simulation {
  DesignReport report;
  PlanarPressureMap map;
};
std::optional<Simulation> Simulate(const Scenario& scenario, SimulatedSide side) {
  std::cout << "solving the equilibrium of the body placed on the support\n";
  DesignReport report = SolveOnSupport(scenario);
  if (StopOnSignals::stopped()) {
    std::cerr << "ergo_validate: interrupted before any result; nothing written\n";
    return std::nullopt;
  }
  if (!report.evaluation.ok) {
    std::cerr << "ergo_validate: the body placed on the support did not reach equilibrium: "
              << report.evaluation.message << "; nothing written\n";
    return std::nullopt;
  }
  std::cout << report.evaluation.equilibrium.BriefReport() << "\n";
  PlanarPressureMap map = SimulatedPressureMap(scenario, report, side);
  if (!(map.sample_pressure().maxCoeff() > 0)) {
    std::cerr << "ergo_validate: the simulated " << SimulatedSideName(side)
              << " carries no pressure at equilibrium; nothing written\n";
    return std::nullopt;
  }
  if (map.unplaced_force() > 1e-3 * map.TotalForce()) {
    std::cerr << "ergo_validate: warning: " << map.unplaced_force()
              << " N of the contact force sits on skin vertices with no downward-facing "
                 "triangle around them and is not in the map\n";
  }
  return Simulation{std::move(report), std::move(map)};
}

// The comparison and alignment grids span the scene and the measured map wherever alignment
// may put it: at most the scene's extent (support and body seen from above) plus the measured
// map's diagonal on either side. Refused above 5 million nodes (two fields of 40 MB each):
// a foot on a 2 mm grid needs about 0.1 million, a 1 m plate export about 1.3 million.
constexpr double kMaxGridNodes = 5e6;
void CheckComparisonGridSize(const Scenario& scenario, double measured_diagonal,
                             const std::string& file) {
  Eigen::Vector2d lower = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d upper = -lower;
  for (const Vertices* points : {&scenario.support.vertices, &scenario.body->rest().vertices}) {
    for (Eigen::Index i = 0; i < points->rows(); ++i) {
      const Eigen::Vector2d q((*points)(i, 0), (*points)(i, 2));
      lower = lower.cwiseMin(q);
      upper = upper.cwiseMax(q);
    }
  }
  const double span = (upper - lower).maxCoeff() + 2 * measured_diagonal;
  const double nodes = std::pow(span / (1e-3 * FLAGS_grid_pitch_mm) + 1, 2);
  if (nodes > kMaxGridNodes) {
    std::ostringstream what;
    what << "comparing with " << file << " (" << measured_diagonal << " m across) on a "
         << FLAGS_grid_pitch_mm << " mm grid would take up to " << nodes
         << " grid nodes, more than 5 million";
    throw InputError("--grid_pitch_mm", "", what.str(),
                     "crop the export to the foot, check its pitch (mm), or give a coarser "
                     "--grid_pitch_mm");
  }
}

int ExitAfterFailure() { return StopOnSignals::stopped() ? StopOnSignals::ExitCode() : 1; }

void WriteSyntheticPlate(const PlanarPressureMap& simulated) {
  SyntheticPlateOptions options;
  options.pitch = 1e-3 * FLAGS_synthetic_pitch_mm;
  options.rotation = FLAGS_synthetic_rotation_deg * kDegree;
  options.shift = ParseShift(FLAGS_synthetic_shift_mm);
  options.noise = FLAGS_synthetic_plate_noise;
  options.seed = static_cast<uint32_t>(FLAGS_synthetic_seed);
  const SyntheticPlate plate = MakeSyntheticPlate(simulated, options);
  std::ostringstream motion;
  motion.precision(17);
  motion << "synthetic_plate_to_support: angle_deg=" << plate.plate_to_map.angle / kDegree
         << " tx_mm=" << 1e3 * plate.plate_to_map.translation.x()
         << " tz_mm=" << 1e3 * plate.plate_to_map.translation.y();
  std::ostringstream made;
  made << "ergo_validate --write_synthetic_plate: the simulated map rotated "
       << FLAGS_synthetic_rotation_deg << " deg about its centre of pressure, shifted "
       << FLAGS_synthetic_shift_mm << " mm, cells averaged, noise " << FLAGS_synthetic_plate_noise
       << " of the peak (seed " << FLAGS_synthetic_seed << ")";
  WritePressurePlateCsv(FLAGS_write_synthetic_plate, plate.grid, "kPa", {made.str(), motion.str()});
  std::cout << "wrote " << FLAGS_write_synthetic_plate << ": " << plate.grid.rows() << " x "
            << plate.grid.columns() << " cells of " << FLAGS_synthetic_pitch_mm << " mm, "
            << plate.grid.TotalForce() << " N; " << motion.str() << "\n";
}

void WriteSyntheticSensors(const PlanarPressureMap& simulated, const SupportTop& top) {
  SyntheticSensorOptions options;
  options.pitch = 1e-3 * FLAGS_synthetic_sensor_pitch_mm;
  options.samples = FLAGS_synthetic_samples;
  options.noise = FLAGS_synthetic_sensor_noise;
  options.posture = FLAGS_synthetic_posture;
  options.outliers = FLAGS_synthetic_outliers;
  options.seed = static_cast<uint32_t>(FLAGS_synthetic_seed);
  const SensorReadings readings = MakeSyntheticSensorReadings(simulated, top, options);
  if (readings.sensors.empty()) {
    throw InputError("--synthetic_sensor_pitch_mm", "",
                     "no location of the lattice lies on the support's top",
                     "give a smaller spacing");
  }
  std::ostringstream made;
  made << "ergo_validate --write_synthetic_sensors: " << readings.sensors.size()
       << " locations every " << FLAGS_synthetic_sensor_pitch_mm << " mm, " << options.samples
       << " samples each, noise " << options.noise << ", posture spread " << options.posture
       << ", outliers " << options.outliers << " (seed " << FLAGS_synthetic_seed
       << "); value and reference in volts at " << options.gain << " and " << options.reference_gain
       << " V/Pa";
  WriteSensorReadingsCsv(FLAGS_write_synthetic_sensors, readings, {made.str()});
  std::cout << "wrote " << FLAGS_write_synthetic_sensors << ": " << readings.sensors.size()
            << " sensor locations, " << options.samples << " samples each\n";
}

void Plot(const std::string& dir) { RunPictureScript("ergo_validate", "plot_validation.py", dir); }

int Run() {
  const RunFlags flags = ValidateRunFlags();
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  StopOnSignals signals;
  const bool synthetic =
      !FLAGS_write_synthetic_plate.empty() || !FLAGS_write_synthetic_sensors.empty();
  std::optional<OutputDirectory> output;
  if (!synthetic) output.emplace(FLAGS_out, "--out");  // writable, checked before any work

  // The measurement first: a bad file is refused before the scene is built.
  std::optional<PressurePlateReading> plate;
  std::optional<SensorReadings> readings;
  if (!FLAGS_plate.empty()) {
    PlateCsvOptions options;
    options.pitch_mm = FLAGS_plate_pitch;
    options.unit = FLAGS_plate_unit;
    plate = ReadPressurePlateCsv(FLAGS_plate, options, "plate_pitch", "plate_unit");
    std::cout << "plate " << FLAGS_plate << ": " << plate->grid.rows() << " x "
              << plate->grid.columns() << " cells of " << 1e3 * plate->grid.pitch
              << " mm (pitch from " << (plate->pitch_source.empty() ? "?" : plate->pitch_source)
              << "), unit " << plate->unit
              << (plate->unit_source.empty() ? "" : " from " + plate->unit_source) << ", total "
              << plate->grid.TotalForce() << " N\n";
  }
  if (!FLAGS_sensors.empty()) {
    readings = ReadSensorReadingsCsv(FLAGS_sensors);
    std::cout << "sensors " << FLAGS_sensors << ": " << readings->sensors.size() << " locations"
              << (readings->has_reference ? " with a reference" : ", no reference column");
    for (const std::string& column : readings->ignored_columns)
      std::cout << "; column '" << column << "' ignored";
    std::cout << "\n";
  }

  const Scenario scenario = PrepareScenario();
  const double load = FLAGS_load_n > 0 ? FLAGS_load_n : SceneLoad(scenario);
  std::optional<SupportTop> top;
  std::optional<SensorPressureMap> sensor_map;
  if (readings || !FLAGS_write_synthetic_sensors.empty())
    top.emplace(scenario.support, "the scene's support");
  if (readings) {
    SensorMapOptions options;
    options.trim = flags.trim;
    options.load = load;
    sensor_map = EstimateSensorPressureMap(*readings, *top, options);
    std::cout << "measured map: " << sensor_map->BriefReport() << "\n";
  }

  if (plate) {
    const double diagonal =
        plate->grid.pitch * std::hypot(static_cast<double>(plate->grid.rows()),
                                       static_cast<double>(plate->grid.columns()));
    CheckComparisonGridSize(scenario, diagonal, FLAGS_plate);
  }
  if (readings)
    CheckComparisonGridSize(scenario, (top->upper() - top->lower()).norm(), FLAGS_sensors);

  const std::optional<Simulation> simulation = Simulate(scenario, flags.side);
  if (!simulation) return ExitAfterFailure();
  const PlanarPressureMap& simulated = simulation->map;
  if (synthetic) {  // one solve for both files when both are asked for
    if (!FLAGS_write_synthetic_plate.empty()) WriteSyntheticPlate(simulated);
    if (!FLAGS_write_synthetic_sensors.empty()) WriteSyntheticSensors(simulated, *top);
    return 0;
  }

  ValidationRecord record;
  record.scenario = scenario.name;
  record.description = scenario.description;
  record.simulated_side = SimulatedSideName(flags.side);
  record.load = load;
  std::optional<PlanarPressureMap> measured;
  if (plate) {
    PressureGrid grid = plate->grid;
    const double measured_force = grid.TotalForce();
    if (FLAGS_plate_to_load) grid.pressure *= load / measured_force;
    measured = PlanarPressureMap::FromGrid(grid);
    record.measurement_kind = "plate";
    record.measurement_file = FLAGS_plate;
    record.measurement["rows"] = plate->grid.rows();
    record.measurement["columns"] = plate->grid.columns();
    record.measurement["pitch_mm"] = 1e3 * plate->grid.pitch;
    record.measurement["pitch_source"] = plate->pitch_source;
    record.measurement["unit"] = plate->unit;
    record.measurement["unit_source"] =
        plate->unit_source.empty() ? "the file" : plate->unit_source;
    record.measurement["force_as_read_n"] = measured_force;
    record.measurement["scaled_to_load"] = FLAGS_plate_to_load;
  } else {
    const SupportTop& support_top = *top;
    measured =
        PlanarPressureMap::FromSurface(support_top.surface(), sensor_map->top_pressure,
                                       support_top.vertex_areas(), PlanarPressureMap::Facing::kUp);
    record.measurement_kind = "sensors";
    record.measurement_file = FLAGS_sensors;
    record.measurement["locations"] = sensor_map->sensors.size();
    record.measurement["has_reference"] = readings->has_reference;
    record.measurement["trim"] = FLAGS_trim;
    record.measurement["scale_c"] = sensor_map->scale;
    record.measurement["reference_variation"] = sensor_map->reference_variation;
    record.measurement["lowest_interpolated_kpa"] = 1e-3 * sensor_map->lowest_interpolated;
    record.measurement["clamped_area_cm2"] = 1e4 * sensor_map->clamped_area;
    record.measurement["top_vertices"] = support_top.surface().vertices.rows();
    record.sensors = &*sensor_map;
  }

  const double threshold = FLAGS_footprint_fraction * simulated.sample_pressure().maxCoeff();
  record.alignment_options.mode = flags.align;
  record.alignment_options.score = flags.align_by;
  record.alignment_options.footprint_threshold = threshold;
  record.alignment_options.grid_pitch = 1e-3 * FLAGS_grid_pitch_mm;
  record.alignment = AlignPressureMaps(simulated, *measured, record.alignment_options);
  record.alignment_description = record.alignment.Describe(*measured);
  std::cout << "alignment: " << record.alignment_description << "\n";
  ComparisonOptions comparison;
  comparison.regions = flags.regions;
  comparison.axis_toward = flags.region_axis;
  comparison.footprint_threshold = threshold;
  comparison.grid_pitch = 1e-3 * FLAGS_grid_pitch_mm;
  if (plate) comparison.measured_cell_pitch = plate->grid.pitch;
  record.comparison =
      ComparePressureMaps(simulated, measured->Moved(record.alignment.motion), comparison);
  std::cout << record.comparison.BriefReport() << "\n";
  if (StopOnSignals::stopped()) {
    std::cerr << "ergo_validate: interrupted; nothing written\n";
    return StopOnSignals::ExitCode();
  }

  WriteValidationFiles(output->path(), record);
  if (FLAGS_plot && !StopOnSignals::stopped()) Plot(output->path());
  std::string error;
  if (!output->Commit(&error)) {
    std::cerr << "ergo_validate: " << error << "\n";
    return 1;
  }
  std::cout << "wrote " << output->final_path() << "/\n";
  return StopOnSignals::stopped() ? StopOnSignals::ExitCode() : 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetCommandLineOptionWithMode("scenario", "shoe", gflags::SET_FLAGS_DEFAULT);
  gflags::SetUsageMessage(
      "compare a simulated contact-pressure map with a measured one\n"
      "  ergo_validate --flagfile=data/shoe.flags (--sensors=readings.csv | --plate=export.csv) "
      "--out=DIR\n"
      "  ergo_validate --flagfile=data/shoe.flags --write_synthetic_plate=FILE "
      "[--synthetic_rotation_deg=8 --synthetic_shift_mm=12,-7]\n"
      "  ergo_validate --flagfile=data/shoe.flags --write_synthetic_sensors=FILE");
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_validate: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_validate: " << error.what() << "\n";
    return 2;
  }
}
