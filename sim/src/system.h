// Internal: the assembled system of an element network (nodes, states, roots) and its
// evaluation: forces, the KKT solve of accelerations and constraint torques per group of
// coupled nodes, derivatives, root functions, the event iteration of the modes.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model.h"

namespace highlift::sim::detail {

/// How System::SolveEquilibrium forms its Jacobian.
struct EquilibriumOptions {
  /// Twists that share no row of the Jacobian's sparsity pattern (jacobian_rows()) are
  /// perturbed together and their difference quotients taken from one evaluation: the same
  /// quotients to the last bit, from a few evaluations instead of one per twist. false: each
  /// twist alone (always so with massless nodes, whose speeds are solved together).
  bool group_twists = true;
};

/// A greedy colouring of the columns of a pattern (compressed columns, rows sorted; with
/// `entry`, the entries k with entry[k] == 0 left out): the columns of one colour share no
/// row, so one difference quotient gives all of them (Curtis, Powell and Reid).
std::vector<std::vector<int>> ColourColumns(const std::vector<int>& colptr, const std::vector<int>& rows,
                                            const std::vector<char>* entry = nullptr);

class System {
 public:
  explicit System(const Network& network);

  int NumStates() const { return n_states_; }
  int NumRoots() const { return n_roots_; }
  const std::vector<std::string>& OutputNames() const { return output_names_; }
  const std::vector<std::string>& StateNames() const { return state_names_; }
  const std::vector<std::unique_ptr<Element>>& elements() const { return elements_; }
  /// Absolute tolerances per state: `absolute` times the state's nominal value (Node and
  /// Element::StateNominals; 1 when none is declared); for a spring twist
  /// torque_tolerance / stiffness when torque_tolerance > 0; for a node's speed at least
  /// `speed_floor` (rad/s; SimulationOptions::speed_resolution times the relative tolerance).
  std::vector<double> AbsoluteTolerances(double absolute, double torque_tolerance, double speed_floor = 0.0) const;
  /// Upper and lower half-bandwidth of the Jacobian (from the element footprints).
  int upper_bandwidth() const { return bandwidth_; }
  int lower_bandwidth() const { return bandwidth_; }
  /// Sparsity pattern of the Jacobian df/dy in compressed columns (a superset over all modes;
  /// the diagonal is always included): rows of column j are
  /// jacobian_rows()[jacobian_colptr()[j] .. jacobian_colptr()[j + 1]).
  const std::vector<int>& jacobian_colptr() const { return jacobian_colptr_; }
  const std::vector<int>& jacobian_rows() const { return jacobian_rows_; }
  /// The part of that pattern the discrete mode of the last evaluation can make nonzero, and a
  /// colouring of its columns. The superset pattern joins every group of nodes that a
  /// constraint may couple (a brake that may stick), and every state of a node or an element
  /// to every other in its cliques. In a mode only the active constraints couple nodes; an
  /// angle's or a twist's derivative is a speed (SpeedRows); a node's angle that no law reads
  /// (Element::ReadsNodeAngles) has no column. A column's entries are then fewer and more
  /// columns share a colour.
  struct ModePattern {
    std::vector<int> key;                   ///< the active constraints (ConstraintSignature)
    std::vector<char> entry;                ///< per entry of jacobian_rows(): in the mode's pattern
    std::vector<std::vector<int>> colours;  ///< columns that share no row of the mode's pattern
  };
  /// The ModePattern of the last evaluation's active constraints (built once per pattern of
  /// constraints and kept, up to kModePatterns of them), or null when the superset's colouring
  /// is the one to use: a network with hydraulic nodes, or an active constraint that couples
  /// nodes outside the superset's groups.
  const ModePattern* ModeJacobianPattern();
  /// Whether the last evaluation's active constraints are those of `pattern`.
  bool InMode(const ModePattern& pattern) const { return SignatureMatches(pattern.key); }
  /// Per state, the states its derivative depends on when those are speeds alone, in every
  /// mode: a node angle on the node's speed, a massless node's held speed state on nothing, a
  /// relative angle (Element::StateSpeedNodes) on the speeds of its nodes when none of them is
  /// massless. No value for every other state.
  std::vector<std::optional<std::vector<int>>> SpeedRows() const;

  /// Consistent initial node angles and speeds and element states (throws InputError for
  /// contradictory initial values).
  std::vector<double> InitialState(double t0);

  /// True when some element declares an initial equation a = a_start
  /// (Element::InitialAccelerations).
  bool HasInitialAccelerations() const;

  /// The initial equations on derivatives, after InitialState and the initial modes: a =
  /// a_start of the elements that declare it and, for a steady-state start, a = 0 at every node
  /// with inertia and a constant twist (der(phi_rel) = 0) of every spring. The unknowns are the
  /// start values that InitialState's equations leave free (the null space of those linear
  /// equations: values not given and guesses, fixed = false); they are solved by Gauss-Newton
  /// (difference-quotient Jacobian) and y is updated. Free values that no equation involves keep
  /// their start values. Returns a one-line account for the event list ("" when there are no
  /// such equations). Throws InputError naming the element and the remedy when the equations are
  /// over-determined (one that no free start value changes does not hold), under-determined
  /// (free values they involve are not all determined) or have no solution.
  std::string SolveInitialAccelerations(double t, std::vector<double>& y, bool steady_state);

  /// The static equilibrium at rest: the spring twists (Element::TwistStates) for which every
  /// node acceleration vanishes with the speeds of y (Gauss-Newton, difference-quotient
  /// Jacobian), written into y when the equilibrium is found. Returns the largest torque
  /// imbalance left at a node (N*m) and sets `found`; y is unchanged when none is found (for
  /// instance nothing holds the loads).
  double SolveEquilibrium(double t, double* y, bool& found, const EquilibriumOptions& options = {});
  /// The model evaluations the last SolveEquilibrium made.
  int equilibrium_evaluations() const { return equilibrium_evaluations_; }

  /// The start of one node for a Modelica tool (StartOfFreeNodes).
  struct NodeStart {
    int node = -1;
    bool fix_phi = false;  ///< the angle is one of the independent free ones
    bool fix_w = false;    ///< the speed is one of the independent free ones
    double phi = 0.0;      ///< rad (m), consistent with the twists and gears
    double w = 0.0;        ///< rad/s (m/s)
  };
  /// The start at y (after InitialState and the initial events) as start values of nodes: the
  /// node angles made consistent with the twist states of the compliant elements and with the
  /// gears (the solution nearest to the angles of y; `inconsistency` is the largest residual,
  /// rad), and an independent set of nodes, taken in the order of `candidates`, whose angles
  /// (speeds) the gears and the elements' own initial values leave free: fixing those determines
  /// every angle (speed). Free nodes that `candidates` leaves out (other than massless nodes,
  /// whose angle is no state) are appended with node >= 0 and neither flag.
  std::vector<NodeStart> StartOfFreeNodes(const double* y, const std::vector<int>& candidates,
                                          double& inconsistency);
  /// The node of a flange "element.port" of the network given to the constructor (a composite's
  /// port included); -1 when there is none.
  int NodeOfPort(const std::string& port) const;
  const std::vector<Node>& nodes() const { return nodes_; }

  /// Full evaluation at (t, y). ydot may be null. Returns false with `error` set on failure.
  bool Evaluate(double t, const double* y, double* ydot);
  /// Whether the elements hold the evaluation of (t, y) (the last one, in the same segment):
  /// Evaluate(t, y, nullptr) would then return at once, and the readings below are its.
  bool IsEvaluatedAt(double t, const double* y) const { return cache_enabled_ && AtLastEvaluation(t, y); }
  /// Root functions (after Evaluate at the same point).
  void Roots(double* g) const;
  /// The root functions at (t, y) into g, evaluated without the forces and the solve, when no
  /// element's roots need them in its present mode (Element::RootsNeedSolve; nor reads a signal
  /// computed after the solve): then true, with the values Evaluate(t, y) and Roots(g) would
  /// give, and the last full evaluation is no longer current. Otherwise false, with g and the
  /// evaluation untouched.
  bool RootsWithoutSolve(double t, const double* y, double* g);
  /// Whether root k is kinematic: a root without restart that is a function of the node angles
  /// and speeds alone (Element::RootFromStates). The simulator locates those itself on the
  /// interpolant with KinematicRoots instead of evaluating the whole model at every trial point.
  bool KinematicRoot(int k) const { return kinematic_root_[k] != 0; }
  bool HasKinematicRoots() const { return !kinematic_root_elements_.empty(); }
  /// The kinematic roots at (t, y) into g[k] (the other entries are left alone), from the node
  /// angles and speeds only: no forces, no solve. The last full evaluation is no longer current.
  void KinematicRoots(double t, const double* y, double* g);
  void RootDirections(int* direction) const;
  double NextTimeEvent(double t) const;

  /// Event handling at time t on state y (modified in place: speeds projected onto the active
  /// constraints). Returns false with `error` on failure. `changes` lists "element: A -> B".
  bool HandleEvent(double t, double* y, bool initial, std::vector<std::string>* changes,
                   std::vector<std::string>* changed_elements, const int* root_info = nullptr);
  void AfterEventRow();

  /// A root without restart (Element::RootRestarts false) was crossed at (t, y): the elements
  /// whose roots fired update their discrete variables (Element::ContinuousRoot). The elements
  /// are left unevaluated: Evaluate(t, y) gives the values with the new discrete variables.
  bool HandleContinuousRoots(double t, const double* y, const int* root_info);
  /// True when some fired root needs the full event treatment.
  bool NeedsRestart(const int* root_info) const;

  /// Outputs of the last Evaluate.
  void Outputs(double* out) const;
  /// The elements whose readings may say something (Element::HasReadings), in order: the run
  /// reads and monitors only these at each step end.
  const std::vector<int>& ReadingElements() const { return reading_elements_; }
  /// Whether every element outside ReadingElements() reads NaN, 0 and 0 at the last Evaluate.
  bool ReadingsAsDeclared() const;

  /// Energy bookkeeping of the last Evaluate.
  struct EnergyState {
    double kinetic = 0.0;       ///< sum over nodes of J w^2 / 2, J
    double potential = 0.0;     ///< sum of Element::StoredEnergy, J
    double loss_power = 0.0;    ///< sum of Element::LossPower, W
    double source_power = 0.0;  ///< sum of Element::SourcePower, W
  };
  EnergyState Energy() const;
  /// The readings of the last Evaluate at a step end, in one pass over ReadingElements():
  /// for the passivity monitor each element's dissipated power (Element::LossPower, W) into
  /// `loss`, and the power scale sum(|loss| + |source power|) over the elements as the result;
  /// for the peaks each element's torque (Element::PeakTorque, NaN for elements without one)
  /// into `tau`. One entry per element; only those of ReadingElements() are written, the
  /// others are 0 (loss) and NaN (tau) from when the vectors were sized. `lowest` gets the
  /// smallest dissipated power written (+infinity when none; a NaN power is not taken), which
  /// the passivity monitor compares with its threshold instead of scanning `loss` again.
  double StepEndReadings(std::vector<double>& loss, std::vector<double>& tau, double& lowest) const;
  /// Kinetic energy removed by the speed projections of all events so far (J, >= 0).
  double impulsive_loss() const { return impulsive_loss_; }

  void set_segment_start(double t) {
    t_segment_ = t;
    DiscreteStateChanged();
  }
  double segment_start() const { return t_segment_; }
  const std::string& error() const { return error_; }
  const std::string& error_element() const { return error_element_; }

 private:
  /// State indices (node angles and speeds, element states, hydraulic pressures) in the
  /// reverse Cuthill-McKee order of the dependency graph, and the half-bandwidth of the
  /// Jacobian that order gives.
  void AssignStates(const std::map<std::string, int>& signal_source, const std::vector<int>& slot_owner);
  bool Solve();
  /// Nodes without inertia or coupling: massless (Node::massless) when only compliant elements
  /// and sensors act on them; throws InputError naming the flange otherwise.
  void ClassifyMasslessNodes();
  /// The speeds of the massless nodes from their torque balance (into eval_.w).
  void SolveMasslessSpeeds();
  /// The initial twists of springs at massless nodes balanced (the node angle moved).
  void BalanceMasslessTwists(double* y);
  /// The signal outputs of the elements in `order` (and their derivatives when needed).
  void EvaluateSignals(const std::vector<int>& order);
  /// Hydraulic nodes from the hydraulic ports and their connections (see HydraulicNode).
  void BuildHydraulicNodes(const Network& network);
  /// Pressure derivatives of the hydraulic nodes, after the elements' Forces().
  bool HydraulicDerivatives(double* ydot);
  /// The speeds at an event made consistent with the velocity-level constraints: the change of
  /// least kinetic energy, solved per group of nodes that the constraints couple (the KKT matrix
  /// is block diagonal over the groups).
  bool ProjectSpeeds(double* y);
  /// The start state from node angles and speeds (indexed like start_unknown_): element
  /// states (InitStates), hydraulic start pressures when `pressures`, balanced massless nodes.
  void StartState(const Eigen::VectorXd& phi, const Eigen::VectorXd& w, double* y, bool pressures);
  /// "J1.phi" (an Inertia or Mass on node n) or "flange 'x' angle": a start value for messages.
  std::string StartValueName(int node, bool speed) const;

  /// The linear initial equations of the last InitialState (with the holonomic rows) and the
  /// map node -> unknown (-1 for ground nodes): SolveInitialAccelerations frees their null space.
  std::vector<Element::InitialEquation> start_position_, start_speed_;
  std::vector<int> start_unknown_;
  int start_unknowns_ = 0;

  std::vector<std::unique_ptr<Element>> elements_;
  std::vector<Element*> assuming_;  ///< elements with HasAssumptions()
  /// The elements with root functions (NumRoots() > 0, fixed by their parameters), in order:
  /// Roots() runs at every step end and output point and needs no pass over the others.
  std::vector<Element*> root_elements_;
  /// Per entry of root_elements_: whether its signals are computed after the solve (a signal
  /// block fed by a torque sensor), so that its roots may read results of the solve.
  std::vector<char> roots_after_solve_;
  std::vector<int> reading_elements_;  ///< indices of the elements with HasReadings()
  /// The elements each phase of Evaluate calls (all until PrunePhases has run).
  std::vector<Element*> forces_, constraints_, after_solve_, derivatives_;
  /// Per entry of forces_, derivatives_ and reading_elements_: how the loops call it. The
  /// spring-dampers and drags of the torque shafts are the most numerous elements of a drive
  /// model, and their laws are called directly (inlined) rather than through the virtual
  /// functions; the calls and their order are the same either way.
  enum DirectCall : char {
    kVirtual = 0,
    kSpringDamper = 1,  ///< exactly a msl::SpringDamper
    kSmoothFriction = 2,  ///< a StribeckFriction regularised on one node (SmoothOneNodeForces; its readings)
  };
  std::vector<DirectCall> forces_direct_, derivatives_direct_, reading_direct_;
  void MarkDirectCalls();
  bool phases_pruned_ = false;
  void PrunePhases();
  std::vector<Node> nodes_;
  int equilibrium_evaluations_ = 0;
  // The nodes' state indices in compact arrays, for the loops of every evaluation (a Node holds
  // its name and nominal values too: walking nodes_ there reads four times the memory).
  std::vector<double> node_phi0_;           ///< per node: the angle of a ground node
  struct StateNode {
    int node, s_phi, s_w;
    bool massless;
  };
  /// The nodes that are not ground: those with inertia, then the massless ones, each in node order.
  std::vector<StateNode> state_nodes_;
  std::size_t n_massive_state_nodes_ = 0;  ///< the first of state_nodes_: those with inertia
  std::vector<int> ground_nodes_;       ///< the ground nodes, in node order
  std::map<std::string, int> port_node_;  ///< flange "element.port" -> node (flat and composite)
  std::vector<int> massless_;                        ///< massless nodes
  std::vector<std::vector<int>> massless_elements_;  ///< the compliant elements on each
  std::vector<int> massless_local_;                  ///< node -> index in massless_ (-1)
  std::vector<HydraulicNode> hnodes_;
  std::vector<std::string> hydraulic_ports_;  ///< "element.port" of every hydraulic port
  std::vector<int> signal_order_;
  /// signal_order_ split: before the solve, and after it (Element::SignalsAfterSolve and the
  /// blocks they feed).
  std::vector<int> signal_order_before_, signal_order_after_;
  bool needs_signal_derivatives_ = false;
  int n_signal_slots_ = 0;
  int n_states_ = 0;
  int n_roots_ = 0;
  int bandwidth_ = 0;
  std::vector<int> jacobian_colptr_, jacobian_rows_;
  std::vector<std::string> state_names_;
  std::vector<std::string> output_names_;
  std::vector<int> output_offset_;
  double t_segment_ = 0.0;
  double impulsive_loss_ = 0.0;
  Eval eval_;
  // The point of the last complete evaluation (an evaluation without derivatives there again
  // returns at once); invalidated whenever the discrete state may change.
  bool cache_valid_ = false, cache_enabled_ = true;
  double cache_t_ = 0.0, cache_segment_ = 0.0;
  std::vector<double> cache_y_;
  std::string error_, error_element_;

  // KKT workspace: the groups of nodes coupled by the active constraints, each with its
  // preallocated system, rebuilt only when the constraint pattern changes (at events).
  struct Group {
    std::vector<int> nodes, rows;  ///< node indices; constraint indices in Eval::constraints
    Eigen::MatrixXd A;
    Eigen::VectorXd b, x;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;  ///< groups larger than kSmallGroup
    Eigen::MatrixXd lu_work;                  ///< the factored copy of A, small groups
    bool schur = false;                       ///< every node has inertia: SolveSchur
    // SolveSchur's view of the constraint pattern (fixed while the signature matches): the
    // inverse inertia of each node, and per constraint (in `rows` order) its column and row entries on
    // the group's nodes (ground entries left out) as the entry's position in
    // Constraint::column / row and the node's local index, entries [begin[k], begin[k + 1]).
    std::vector<double> inverse_J;
    std::vector<int> column_begin, column_entry, column_local;
    std::vector<int> row_begin, row_entry, row_local;
  };
  bool SolveSchur(Group& g);     ///< a group with two or more constraints (Solve picks)
  bool SolveSchurOne(Group& g);  ///< SolveSchur of a group with one constraint
  /// The commonest group, flattened by BuildGroups: two nodes with inertia and one constraint
  /// with an entry on each node in its column and in its row (a gear, a rigid coupling: 594 000
  /// of the 645 000 group solves of rupture_wtb). Solve runs these first, in one tight loop over
  /// this compact array, rather than through their Group (vectors behind pointers); the groups
  /// are independent (no node in two), so the order of their solves does not matter.
  struct PairGroup {
    int node[2];
    double inverse_J[2];
    int row;  ///< the constraint's index in Eval::constraints
    int column_entry[2], column_local[2], row_entry[2], row_local[2];
    int group;  ///< its index in groups_ (solved as a Group when SolvePair finds it singular)
  };
  bool SolvePair(const PairGroup& p);  ///< SolveSchurOne's two-node case, the same operations
  bool SolveGroup(Group& g);           ///< Solve's work for one group that is not a pair
  std::vector<PairGroup> pair_groups_;
  std::vector<int> other_groups_;  ///< the indices in groups_ of the groups that are not pairs
  /// The first part of every evaluation: node angles and speeds from y (the massless nodes'
  /// speeds solved), hydraulic pressures, forces and accelerations cleared.
  void SetKinematics(double t, const double* y);
  /// (t, y) is the point of the last complete evaluation, still current.
  bool AtLastEvaluation(double t, const double* y) const;
  std::vector<char> kinematic_root_;               ///< per root: KinematicRoot
  std::vector<Element*> kinematic_root_elements_;  ///< the elements with a kinematic root
  std::vector<double> kinematic_scratch_;          ///< one element's roots
  static constexpr int kSmallGroup = 16;  ///< up to this size: our own elimination
  void ConstraintSignature(std::vector<int>& signature) const;
  /// The active constraints have the pattern of `signature` (by default signature_).
  bool SignatureMatches(const std::vector<int>& signature) const;
  bool SignatureMatches() const { return SignatureMatches(signature_); }
  /// The active constraints were found to have the pattern of signature_ since the discrete
  /// state last changed. An element's constraints are a function of its discrete state (its
  /// mode), so between events Solve leaves out SignatureMatches (debug builds assert it).
  /// Cleared wherever the discrete state may change (DiscreteStateChanged, a branch reassumed
  /// in Evaluate); never set inside the event iteration (HandleEvent), where the modes change
  /// between the solves.
  bool pattern_current_ = false;
  /// The discrete state may have changed: the evaluation cache and the constraints' pattern are
  /// no longer known to be current.
  void DiscreteStateChanged() {
    cache_valid_ = false;
    pattern_current_ = false;
  }
  void BuildGroups();
  std::vector<Group> groups_;
  /// The free nodes with inertia in no constraint, with their inertia: acc = force / J.
  std::vector<std::pair<int, double>> unconstrained_;
  std::vector<int> grounded_rows_;   ///< constraints between ground nodes only
  std::vector<int> signature_;
  // What ModeJacobianPattern builds on (AssignStates): per element the states of its footprint,
  // and the cliques of the pattern that no constraint forms (massless chains, hydraulic nodes).
  std::vector<std::vector<int>> footprint_states_;
  std::vector<std::vector<int>> fixed_cliques_;
  std::map<std::vector<int>, ModePattern> mode_patterns_;  ///< by ConstraintSignature
  /// At most this many kept (about 8 KB each on the A380-class model; a run that chatters
  /// through more modes starts the cache afresh rather than grow).
  static constexpr std::size_t kModePatterns = 64;
  std::vector<int> mode_key_;                             ///< scratch
  std::vector<std::optional<std::vector<int>>> speed_rows_;  ///< SpeedRows (on first use)
  std::vector<std::vector<int>> element_nodes_;  ///< per element: its nodes that are not ground
  std::vector<char> node_state_;    ///< per state: a node's angle or speed
  std::vector<char> unread_angle_;  ///< per state: the angle of a node no law reads (Element::ReadsNodeAngles)
  std::vector<int> parent_;
  std::vector<int> local_;
  std::vector<char> in_constraint_;
};

}  // namespace highlift::sim::detail
