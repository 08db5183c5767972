#include "system.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <typeinfo>

#include <Eigen/Sparse>

#include "composites.h"
#include "brake_elements.h"
#include "msl_elements.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::sim::detail {

double FixedAngle(const Element& element);  // elements.cc

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n = 0) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int Find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void Unite(int i, int j) { parent[Find(i)] = Find(j); }
};

std::string Join(const std::vector<std::string>& v, const std::string& sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

// The solution of E x = d nearest to the start values that are guesses: x = guess + D y with
// D = 1 for the values without a guess (guess 0) and 1e-3 for the guessed ones, y of minimum
// norm (normal equations with a tiny regularization, sparse). A guessed value therefore moves
// only where the equations determine it (as a Modelica tool prefers the explicit start values).
Eigen::VectorXd MinimumNormScaled(const std::vector<Element::InitialEquation>& rows,
                                  const std::vector<int>& unknown, const std::vector<double>& known,
                                  int n_unknown, const Eigen::VectorXd& guess, const Eigen::VectorXd& D,
                                  Eigen::VectorXd& d);

Eigen::VectorXd MinimumNorm(const std::vector<Element::InitialEquation>& rows,
                            const std::vector<int>& unknown, const std::vector<double>& known,
                            int n_unknown, const Eigen::VectorXd& guess, const std::vector<char>& guessed,
                            Eigen::VectorXd& d) {
  Eigen::VectorXd D = Eigen::VectorXd::Ones(n_unknown);
  for (int k = 0; k < n_unknown; ++k)
    if (guessed[k]) D[k] = 1e-3;
  return MinimumNormScaled(rows, unknown, known, n_unknown, guess, D, d);
}

// The solution x = guess + D y of E x = d with y of minimum norm: an unknown with a small D
// moves little.
Eigen::VectorXd MinimumNormScaled(const std::vector<Element::InitialEquation>& rows,
                                  const std::vector<int>& unknown, const std::vector<double>& known,
                                  int n_unknown, const Eigen::VectorXd& guess, const Eigen::VectorXd& D,
                                  Eigen::VectorXd& d) {
  const int m = static_cast<int>(rows.size());
  d.resize(m);
  Eigen::VectorXd x = guess;
  if (m == 0 || n_unknown == 0) {
    for (int i = 0; i < m; ++i) {
      double r = rows[i].value;
      for (auto [node, coef] : rows[i].row) r -= coef * known[node];
      d[i] = r;
    }
    return x;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < m; ++i) {
    double r = rows[i].value;
    for (auto [node, coef] : rows[i].row) {
      if (unknown[node] >= 0) triplets.emplace_back(i, unknown[node], coef);
      else r -= coef * known[node];
    }
    d[i] = r;
  }
  Eigen::SparseMatrix<double> E(m, n_unknown);
  E.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> ED = E * D.asDiagonal();
  Eigen::SparseMatrix<double> EEt = ED * ED.transpose();
  double scale = 0.0;
  for (int k = 0; k < EEt.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(EEt, k); it; ++it)
      scale = std::max(scale, std::abs(it.value()));
  Eigen::SparseMatrix<double> I(m, m);
  I.setIdentity();
  EEt += I * (1e-13 * std::max(scale, 1.0));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(EEt);
  if (ldlt.info() != Eigen::Success) return x;
  // Iterative refinement removes the bias of the regularization (long chains of relative
  // initial angles make E*E^T ill-conditioned).
  const Eigen::VectorXd rhs = d - E * guess;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n_unknown);
  for (int pass = 0; pass < 30; ++pass) {
    const Eigen::VectorXd r = rhs - ED * y;
    if (r.norm() <= 1e-14 * (1.0 + d.norm())) break;
    y += ED.transpose() * ldlt.solve(r);
  }
  return guess + D.cwiseProduct(y);
}

}  // namespace

System::System(const Network& original) {
  // Composite types become their parts.
  std::map<std::string, std::vector<std::string>> composite_ports;
  const Network network = FlattenComposites(original, &composite_ports);
  // Elements.
  std::map<std::string, int> element_index;
  for (const auto& ne : network.elements()) {
    auto el = MakeElement(ne);
    el->index = static_cast<int>(elements_.size());
    element_index[ne.id] = el->index;
    elements_.push_back(std::move(el));
  }
  // Signal output slots.
  std::map<std::string, int> output_slot;  // "element.port" -> slot
  std::vector<int> slot_owner;             // slot -> element
  for (auto& el : elements_) {
    const auto outputs = el->SignalOutputs();
    if (outputs.empty()) continue;
    el->signal_offset = static_cast<int>(slot_owner.size());
    for (const auto& o : outputs) {
      output_slot[el->id + "." + o] = static_cast<int>(slot_owner.size());
      slot_owner.push_back(el->index);
    }
  }
  n_signal_slots_ = static_cast<int>(slot_owner.size());
  BuildHydraulicNodes(network);
  // Flange ports and their union.
  std::map<std::string, int> port_index;
  std::vector<std::string> port_name;
  std::vector<bool> port_is_support;
  for (const auto& el : elements_)
    for (const auto& f : el->Flanges()) {
      port_index[el->id + "." + f] = static_cast<int>(port_name.size());
      port_name.push_back(el->id + "." + f);
      port_is_support.push_back(f.rfind("support", 0) == 0);  // support, supportR, supportT
    }
  UnionFind ports(static_cast<int>(port_name.size()));
  std::vector<int> degree(port_name.size(), 0);
  for (const auto& el : elements_)
    for (const auto& group : el->RigidFlanges())
      for (std::size_t k = 1; k < group.size(); ++k)
        ports.Unite(port_index.at(el->id + "." + group[0]), port_index.at(el->id + "." + group[k]));
  // Signal connections: input port -> source element.
  std::map<std::string, int> signal_source;
  for (const auto& c : network.connections()) {
    const std::string a = c.a.ToString(), b = c.b.ToString();
    if (std::binary_search(hydraulic_ports_.begin(), hydraulic_ports_.end(), a) ||
        std::binary_search(hydraulic_ports_.begin(), hydraulic_ports_.end(), b))
      continue;  // BuildHydraulicNodes
    auto ia = port_index.find(a), ib = port_index.find(b);
    if (ia != port_index.end() && ib != port_index.end()) {
      ports.Unite(ia->second, ib->second);
      ++degree[ia->second];
      ++degree[ib->second];
      continue;
    }
    if (ia != port_index.end() || ib != port_index.end())
      throw InputError("connection " + a + " - " + b +
                       ": a flange can only be connected to a flange; connect signal ports "
                       "(y, u, tau, f_normalized, w_ref) to each other");
    const PortRef* out = nullptr;
    const PortRef* in = nullptr;
    const bool a_out = output_slot.count(a) > 0, b_out = output_slot.count(b) > 0;
    if (a_out && !b_out) out = &c.a, in = &c.b;
    else if (b_out && !a_out) out = &c.b, in = &c.a;
    if (out == nullptr)
      throw InputError("connection " + a + " - " + b +
                       ": a signal connection joins one output (such as 'y') to one input");
    const std::string key = in->ToString();
    if (signal_source.count(key))
      throw InputError("signal input '" + key + "' is connected twice; connect it to one output");
    signal_source[key] = output_slot.at(out->ToString());
  }
  // Nodes.
  std::map<int, int> root_to_node;
  std::vector<int> port_node(port_name.size());
  std::vector<int> root_size(port_name.size(), 0);
  for (std::size_t p = 0; p < port_name.size(); ++p) ++root_size[ports.Find(static_cast<int>(p))];
  for (std::size_t p = 0; p < port_name.size(); ++p) {
    const int r = ports.Find(static_cast<int>(p));
    auto it = root_to_node.find(r);
    if (it == root_to_node.end()) {
      it = root_to_node.emplace(r, static_cast<int>(nodes_.size())).first;
      Node n;
      n.name = port_name[p];
      nodes_.push_back(n);
    }
    port_node[p] = it->second;
    // An unconnected support is the grounded housing (MSL useSupport=false).
    if (port_is_support[p] && root_size[r] == 1 && degree[p] == 0) nodes_[it->second].ground = true;
  }
  for (const auto& el : elements_)
    if (el->type == "Fixed" || el->type == "Translational.Fixed") {
      Node& n = nodes_[port_node[port_index.at(el->id + ".flange")]];
      n.ground = true;
      n.phi0 = FixedAngle(*el);
      n.name = el->id + ".flange";
    }
  for (std::size_t p = 0; p < port_name.size(); ++p) port_node_[port_name[p]] = port_node[p];
  for (const auto& [outer, inner] : composite_ports)
    if (!inner.empty())
      if (auto it = port_index.find(inner.front()); it != port_index.end()) port_node_[outer] = port_node[it->second];
  // Bind ports.
  for (auto& el : elements_) {
    auto node_of = [&](const std::string& port) { return port_node[port_index.at(el->id + "." + port)]; };
    auto signal_of = [&](const std::string& port) {
      auto it = signal_source.find(el->id + "." + port);
      if (it == signal_source.end())
        throw InputError("element '" + el->id + "' (" + el->type + "): signal input '" + port +
                         "' is not connected; connect it to the output 'y' of a signal source "
                         "(Constant, Step, Sine, ...)");
      return it->second;
    };
    el->Bind(node_of, signal_of);
    el->AddInertia(nodes_);
  }
  // Signal evaluation order (inputs first).
  {
    std::vector<int> state(elements_.size(), 0);
    std::function<void(int)> visit = [&](int i) {
      if (state[i] == 2) return;
      if (state[i] == 1)
        throw InputError("signal blocks form an algebraic loop through '" + elements_[i]->id +
                         "'; break the loop");
      state[i] = 1;
      if (elements_[i]->DirectFeedthrough())
        for (const auto& in : elements_[i]->SignalInputs()) {
          auto it = signal_source.find(elements_[i]->id + "." + in);
          if (it != signal_source.end()) visit(slot_owner[it->second]);
        }
      state[i] = 2;
      if (elements_[i]->signal_offset >= 0) signal_order_.push_back(i);
    };
    for (std::size_t i = 0; i < elements_.size(); ++i)
      if (elements_[i]->signal_offset >= 0) visit(static_cast<int>(i));
  }
  // Signals computed from the solve (torque, power and acceleration sensors) and the blocks
  // they feed are evaluated after the solve; a law acting in the solve must not read them.
  std::vector<char> after(elements_.size(), 0);
  {
    std::vector<std::vector<int>> consumers(elements_.size());
    for (const auto& el : elements_)
      for (const auto& in : el->SignalInputs()) {
        auto it = signal_source.find(el->id + "." + in);
        if (it != signal_source.end()) consumers[slot_owner[it->second]].push_back(el->index);
      }
    std::function<void(int, int)> mark = [&](int i, int origin) {
      for (int c : consumers[i]) {
        if (after[c]) continue;
        const Element& consumer = *elements_[c];
        if (!consumer.IsSignalBlock() && !consumer.SignalsAfterSolve())
          throw InputError("element '" + consumer.id + "' (" + consumer.type + ") reads a signal of '" +
                           elements_[origin]->id + "' (" + elements_[origin]->type +
                           "), which is computed from the solved torques or accelerations: a law "
                           "acting in the same solve cannot use it (an algebraic loop); feed it "
                           "to signal blocks or outputs only, or measure a speed or angle instead");
        after[c] = 1;
        mark(c, origin);
      }
    };
    for (const auto& el : elements_)
      if (el->SignalsAfterSolve()) {
        after[el->index] = 1;
        mark(el->index, el->index);
      }
    for (int i : signal_order_) (after[i] ? signal_order_after_ : signal_order_before_).push_back(i);
    for (const auto& el : elements_) needs_signal_derivatives_ = needs_signal_derivatives_ || el->NeedsSignalDerivatives();
  }
  // Roots.
  for (auto& el : elements_) {
    el->root_offset = n_roots_;
    n_roots_ += el->NumRoots();
    if (el->NumRoots() > 0) {
      root_elements_.push_back(el.get());
      roots_after_solve_.push_back(after[static_cast<std::size_t>(el->index)]);
    }
    bool kinematic = false;
    for (int k = 0; k < el->NumRoots(); ++k) {
      const bool from_states = el->RootFromStates(k) && !el->RootRestarts(k);
      kinematic_root_.push_back(from_states ? 1 : 0);
      kinematic = kinematic || from_states;
    }
    if (kinematic) kinematic_root_elements_.push_back(el.get());
    kinematic_scratch_.resize(std::max<std::size_t>(kinematic_scratch_.size(), el->NumRoots()));
  }
  for (std::size_t i = 0; i < elements_.size(); ++i)
    if (elements_[i]->HasReadings()) reading_elements_.push_back(static_cast<int>(i));
  ClassifyMasslessNodes();
  AssignStates(signal_source, slot_owner);
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const Node& node = nodes_[n];
    node_phi0_.push_back(node.phi0);
    if (!node.ground) state_nodes_.push_back({static_cast<int>(n), node.s_phi, node.s_w, node.massless});
    else ground_nodes_.push_back(static_cast<int>(n));
  }
  // The nodes with inertia first: the derivatives' loop then needs no branch per node.
  const auto massless_begin = std::stable_partition(state_nodes_.begin(), state_nodes_.end(),
                                                    [](const StateNode& node) { return !node.massless; });
  n_massive_state_nodes_ = static_cast<std::size_t>(massless_begin - state_nodes_.begin());
  // Outputs.
  for (const auto& el : elements_) {
    output_offset_.push_back(static_cast<int>(output_names_.size()));
    for (const auto& o : el->OutputNames()) output_names_.push_back(el->id + "." + o);
  }
  for (auto& el : elements_)
    if (el->HasAssumptions()) assuming_.push_back(el.get());
  for (auto& el : elements_) {
    forces_.push_back(el.get());
    constraints_.push_back(el.get());
    after_solve_.push_back(el.get());
    derivatives_.push_back(el.get());
  }
  MarkDirectCalls();
  // Workspace.
  eval_.phi.assign(nodes_.size(), 0.0);
  eval_.w.assign(nodes_.size(), 0.0);
  // A ground node's angle and speed never change (nothing writes them but with these values):
  // set here once, not at every evaluation (SetKinematics).
  for (int n : ground_nodes_) eval_.phi[static_cast<std::size_t>(n)] = node_phi0_[static_cast<std::size_t>(n)];
  eval_.acc.assign(nodes_.size(), 0.0);
  eval_.force.assign(nodes_.size(), 0.0);
  eval_.signal.assign(n_signal_slots_, 0.0);
  eval_.signal_d1.assign(n_signal_slots_, NAN);
  eval_.signal_d2.assign(n_signal_slots_, NAN);
  eval_.p.assign(hnodes_.size(), 0.0);
  eval_.q.assign(hnodes_.size(), 0.0);
  eval_.cap.assign(hnodes_.size(), 0.0);
  parent_.resize(nodes_.size());
  local_.assign(nodes_.size(), -1);
}

void System::AssignStates(const std::map<std::string, int>& signal_source, const std::vector<int>& slot_owner) {
  const int n_nodes = static_cast<int>(nodes_.size());
  const int n_elements = static_cast<int>(elements_.size());
  const int n_hydraulic = static_cast<int>(hnodes_.size());
  // Blocks of states: a node's (phi, w), an element's own states, a hydraulic node's pressure.
  const int n_blocks = n_nodes + n_elements + n_hydraulic;
  auto element_block = [&](int i) { return n_nodes + i; };
  auto hydraulic_block = [&](int h) { return n_nodes + n_elements + h; };
  std::vector<int> block_size(n_blocks, 0);
  for (int n = 0; n < n_nodes; ++n) block_size[n] = nodes_[n].ground ? 0 : 2;
  for (int i = 0; i < n_elements; ++i) block_size[element_block(i)] = elements_[i]->NumStates();
  for (int h = 0; h < n_hydraulic; ++h) block_size[hydraulic_block(h)] = hnodes_[h].fixed ? 0 : 1;
  auto add = [&](std::vector<int>& set, int block) {
    if (block_size[block] > 0) set.push_back(block);
  };
  auto tidy = [](std::vector<int>& set) {
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  };
  // What each element reads: its nodes, its states, its hydraulic nodes.
  std::vector<std::vector<int>> own(n_elements);
  for (int i = 0; i < n_elements; ++i) {
    for (int n : elements_[i]->Nodes()) add(own[i], n);
    add(own[i], element_block(i));
    for (int h : elements_[i]->HydraulicNodes()) add(own[i], hydraulic_block(h));
    tidy(own[i]);
  }
  // The states a signal output follows: its element's own, and those of its inputs' sources
  // (none for outputs that change only at events).
  std::vector<std::vector<int>> follows(n_elements);
  std::vector<char> state(n_elements, 0);
  std::function<void(int)> visit;
  // Appends the states behind element i's signal inputs to `out`.
  auto append_input_states = [&](int i, std::vector<int>& out) {
    for (const auto& in : elements_[i]->SignalInputs()) {
      auto it = signal_source.find(elements_[i]->id + "." + in);
      if (it == signal_source.end()) continue;
      const int source = slot_owner[it->second];
      visit(source);
      out.insert(out.end(), follows[source].begin(), follows[source].end());
    }
  };
  visit = [&](int i) {
    if (state[i] != 0) return;  // done, or on the stack (loops are rejected above)
    state[i] = 1;
    if (elements_[i]->SignalsFollowState()) {
      follows[i] = own[i];
      append_input_states(i, follows[i]);
      tidy(follows[i]);
    }
    state[i] = 2;
  };
  // Everything an element's law depends on: what it reads and the states behind its inputs.
  std::vector<std::vector<int>> footprint(n_elements);
  for (int i = 0; i < n_elements; ++i) {
    footprint[i] = own[i];
    append_input_states(i, footprint[i]);
    tidy(footprint[i]);
  }
  // Groups of nodes that constraints may couple: their accelerations are solved together, so
  // each depends on every law acting on the group.
  UnionFind groups(n_nodes);
  for (const auto& el : elements_) {
    int first = -1;
    for (int n : el->CoupledNodes()) {
      if (nodes_[n].ground) continue;
      if (first < 0) first = n;
      else groups.Unite(first, n);
    }
  }
  std::vector<std::vector<int>> group_blocks(n_nodes);  // by group root: the node blocks
  for (int n = 0; n < n_nodes; ++n)
    if (!nodes_[n].ground) group_blocks[groups.Find(n)].push_back(n);
  // Cliques of the Jacobian's sparsity: every derivative in a clique may depend on every state
  // in it.
  std::vector<std::vector<int>> cliques;
  std::vector<int> clique_of_group(n_nodes, -1);
  for (int n = 0; n < n_nodes; ++n) {
    if (nodes_[n].ground) continue;
    const int r = groups.Find(n);
    if (clique_of_group[r] < 0) {
      clique_of_group[r] = static_cast<int>(cliques.size());
      cliques.push_back(group_blocks[r]);
    }
  }
  std::vector<std::vector<int>> hydraulic_clique(n_hydraulic);
  for (int i = 0; i < n_elements; ++i) {
    std::vector<int> element_clique = footprint[i];
    for (int n : elements_[i]->Nodes()) {
      if (nodes_[n].ground) continue;
      auto& c = cliques[clique_of_group[groups.Find(n)]];
      c.insert(c.end(), footprint[i].begin(), footprint[i].end());
      const auto& g = group_blocks[groups.Find(n)];
      element_clique.insert(element_clique.end(), g.begin(), g.end());
    }
    for (int h : elements_[i]->HydraulicNodes())
      if (block_size[hydraulic_block(h)] > 0) {
        auto& c = hydraulic_clique[h];
        c.insert(c.end(), footprint[i].begin(), footprint[i].end());
        c.push_back(hydraulic_block(h));
      }
    if (block_size[element_block(i)] > 0) cliques.push_back(std::move(element_clique));
  }
  // A massless node's speed follows from the balance of every compliant element on it (and on
  // the massless nodes next to it): their states form one clique.
  const std::size_t first_fixed_clique = cliques.size();
  if (!massless_.empty()) {
    UnionFind chain(n_nodes);
    for (const auto& el : elements_) {
      int first = -1;
      for (int n : el->Nodes())
        if (nodes_[n].massless) first < 0 ? void(first = n) : chain.Unite(first, n);
    }
    std::map<int, std::vector<int>> clique_of_chain;
    for (int i = 0; i < n_elements; ++i)
      for (int n : elements_[i]->Nodes())
        if (nodes_[n].massless) {
          auto& c = clique_of_chain[chain.Find(n)];
          c.insert(c.end(), footprint[i].begin(), footprint[i].end());
        }
    for (auto& [root, c] : clique_of_chain) cliques.push_back(std::move(c));
  }
  for (auto& c : hydraulic_clique)
    if (!c.empty()) cliques.push_back(std::move(c));
  for (auto& c : cliques) tidy(c);
  // Reverse Cuthill-McKee on the block graph (blocks adjacent when they share a clique).
  std::vector<std::vector<int>> adjacent(n_blocks);
  for (const auto& c : cliques)
    for (int a : c)
      for (int b : c)
        if (a != b) adjacent[a].push_back(b);
  for (auto& a : adjacent) tidy(a);
  std::vector<int> order;
  order.reserve(n_blocks);
  std::vector<char> placed(n_blocks, 0);
  auto degree = [&](int b) { return adjacent[b].size(); };
  auto bfs_from = [&](int root, std::vector<int>& level_order, std::vector<int>& level) {
    level_order.clear();
    level.assign(n_blocks, -1);
    level[root] = 0;
    level_order.push_back(root);
    for (std::size_t k = 0; k < level_order.size(); ++k)
      for (int v : adjacent[level_order[k]])
        if (level[v] < 0) {
          level[v] = level[level_order[k]] + 1;
          level_order.push_back(v);
        }
  };
  std::vector<int> scratch, level;
  for (int start = 0; start < n_blocks; ++start) {
    if (placed[start] || block_size[start] == 0) continue;
    // A pseudo-peripheral root of this component (George and Liu): move to a block of least
    // degree in the last BFS level while that increases the eccentricity.
    int root = start;
    bfs_from(root, scratch, level);
    int eccentricity = level[scratch.back()];
    for (int pass = 0; pass < 8; ++pass) {
      int far = scratch.back();
      for (int v : scratch)
        if (level[v] == eccentricity && degree(v) < degree(far)) far = v;
      bfs_from(far, scratch, level);
      const int e_far = level[scratch.back()];
      if (e_far <= eccentricity) {
        bfs_from(root, scratch, level);
        break;
      }
      root = far;
      eccentricity = e_far;
    }
    // Cuthill-McKee from the root: neighbours by increasing degree.
    const std::size_t first = order.size();
    order.push_back(root);
    placed[root] = 1;
    for (std::size_t k = first; k < order.size(); ++k) {
      std::vector<int> next;
      for (int v : adjacent[order[k]])
        if (!placed[v]) next.push_back(v);
      std::stable_sort(next.begin(), next.end(), [&](int a, int b) { return degree(a) < degree(b); });
      for (int v : next) {
        placed[v] = 1;
        order.push_back(v);
      }
    }
    std::reverse(order.begin() + static_cast<std::ptrdiff_t>(first), order.end());
  }
  // State indices in that order.
  std::vector<int> first_state(n_blocks, -1);
  for (int b : order) {
    first_state[b] = n_states_;
    if (b < n_nodes) {
      nodes_[b].s_phi = n_states_++;
      nodes_[b].s_w = n_states_++;
      state_names_.push_back(nodes_[b].name + ".phi");
      state_names_.push_back(nodes_[b].name + ".w");
    } else if (b < n_nodes + n_elements) {
      Element& el = *elements_[b - n_nodes];
      el.state_offset = n_states_;
      n_states_ += el.NumStates();
      for (const auto& name : el.StateNames()) state_names_.push_back(name);
    } else {
      HydraulicNode& h = hnodes_[b - n_nodes - n_elements];
      h.s_p = n_states_++;
      state_names_.push_back(h.name + ".p");
    }
  }
  for (auto& el : elements_)
    if (el->NumStates() == 0) el->state_offset = n_states_;
  HIGHLIFT_CHECK(static_cast<int>(state_names_.size()) == n_states_, "state names and states disagree");
  // Sparsity of the Jacobian (compressed columns, rows sorted, the diagonal included): column
  // j may have entries in every row of every clique that contains j.
  {
    std::vector<std::vector<int>> clique_states(cliques.size());
    std::vector<std::vector<int>> cliques_of_state(n_states_);
    for (std::size_t c = 0; c < cliques.size(); ++c)
      for (int b : cliques[c])
        for (int k = 0; k < block_size[b]; ++k) {
          clique_states[c].push_back(first_state[b] + k);
          cliques_of_state[first_state[b] + k].push_back(static_cast<int>(c));
        }
    jacobian_colptr_.assign(1, 0);
    jacobian_rows_.clear();
    std::vector<int> rows;
    for (int j = 0; j < n_states_; ++j) {
      rows.assign(1, j);
      for (int c : cliques_of_state[j]) rows.insert(rows.end(), clique_states[c].begin(), clique_states[c].end());
      tidy(rows);
      jacobian_rows_.insert(jacobian_rows_.end(), rows.begin(), rows.end());
      jacobian_colptr_.push_back(static_cast<int>(jacobian_rows_.size()));
    }
  }
  // The inputs of ModeJacobianPattern, in state indices.
  auto states_of = [&](const std::vector<int>& blocks) {
    std::vector<int> states;
    for (int b : blocks)
      for (int k = 0; k < block_size[b]; ++k) states.push_back(first_state[b] + k);
    return states;
  };
  footprint_states_.clear();
  for (int i = 0; i < n_elements; ++i) footprint_states_.push_back(states_of(footprint[i]));
  fixed_cliques_.clear();
  for (std::size_t c = first_fixed_clique; c < cliques.size(); ++c) {
    fixed_cliques_.push_back(states_of(cliques[c]));
    std::sort(fixed_cliques_.back().begin(), fixed_cliques_.back().end());
  }
  mode_patterns_.clear();
  // Half-bandwidth: the widest clique, in state indices.
  bandwidth_ = 1;  // phi' = w within each node's pair
  for (const auto& c : cliques) {
    int lo = std::numeric_limits<int>::max(), hi = -1;
    for (int b : c) {
      lo = std::min(lo, first_state[b]);
      hi = std::max(hi, first_state[b] + block_size[b] - 1);
    }
    if (hi >= 0) bandwidth_ = std::max(bandwidth_, hi - lo);
  }
}

void System::ClassifyMasslessNodes() {
  // Flanges joined only by rigid sensors, none with inertia or fixed: their common acceleration
  // is undetermined (a massless node is solved between springs and dampers only).
  auto rigid_sensor = [](const Element& el) {
    return el.type == "TorqueSensor" || el.type == "PowerSensor" || el.type == "MultiSensor" || el.type == "Disc";
  };
  UnionFind rigid(static_cast<int>(nodes_.size()));
  for (const auto& el : elements_) {
    const auto nodes = el->CoupledNodes();
    for (std::size_t k = 1; k < nodes.size(); ++k) rigid.Unite(nodes[0], nodes[k]);
  }
  std::vector<char> anchored(nodes_.size(), 0);  // inertia, a fixed flange or another coupling
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (nodes_[n].ground || nodes_[n].J > 0) anchored[rigid.Find(static_cast<int>(n))] = 1;
  for (const auto& el : elements_)
    if (!rigid_sensor(*el))
      for (int n : el->CoupledNodes()) anchored[rigid.Find(n)] = 1;
  for (const auto& el : elements_) {
    if (!rigid_sensor(*el) || anchored[rigid.Find(el->CoupledNodes().front())]) continue;
    std::vector<std::string> names;
    for (int n : el->CoupledNodes()) names.push_back(nodes_[n].name);
    throw InputError("element '" + el->id + "' (" + el->type + ") joins flanges " + Join(names) +
                     " rigidly, and none of the flanges joined so has inertia or is fixed: their "
                     "acceleration is undetermined (a flange without inertia is solved as a static "
                     "balance of springs and dampers only); connect it next to an Inertia");
  }
  std::vector<bool> coupled(nodes_.size(), false);
  for (const auto& el : elements_)
    for (int n : el->CoupledNodes()) coupled[n] = true;
  std::vector<std::vector<int>> acting(nodes_.size());
  for (const auto& el : elements_)
    for (int n : el->Nodes()) acting[n].push_back(el->index);
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    Node& node = nodes_[n];
    if (node.ground || node.J > 0 || coupled[n]) continue;
    // A node without inertia: the static balance of the compliant elements on it.
    std::vector<int> compliant;
    for (int i : acting[n]) {
      const Element& el = *elements_[i];
      const auto role = el.RoleAt(static_cast<int>(n));
      if (role == Element::MasslessRole::kCompliant) {
        compliant.push_back(i);
      } else if (role == Element::MasslessRole::kOther) {
        throw InputError("flange '" + node.name + "' has no inertia and no kinematic coupling, and element '" +
                         el.id + "' (" + el.type +
                         ") acts on it with a torque that does not depend on the flange's motion, so its "
                         "acceleration is undetermined; connect an Inertia there or fix it");
      }
    }
    if (compliant.empty())
      throw InputError("flange '" + node.name +
                       "' has no inertia, no kinematic coupling and no spring or damper, so its motion is "
                       "undetermined; connect an Inertia there, a compliant element, or fix it");
    node.massless = true;
    massless_.push_back(static_cast<int>(n));
    massless_elements_.push_back(std::move(compliant));
  }
  massless_local_.assign(nodes_.size(), -1);
  for (std::size_t i = 0; i < massless_.size(); ++i) massless_local_[massless_[i]] = static_cast<int>(i);
  // The balance gives a massless node's angle and speed, not its acceleration (RelativeStates
  // reports a_rel).
  for (const auto& el : elements_)
    if (el->type == "AccSensor" || el->type == "RelAccSensor" || el->type == "RelativeStates")
      for (int n : el->Nodes())
        if (nodes_[n].massless)
          throw InputError("element '" + el->id + "' (" + el->type + ") measures the acceleration of flange '" +
                           nodes_[n].name +
                           "', which has no inertia (a static balance of springs and dampers): its "
                           "acceleration is not computed; measure it at a flange with inertia");
}

// The speeds of the massless nodes: the torque balance sum(T_k) = 0 of the compliant elements
// on each (T_k = Element::BalanceTorque), solved for the node speeds (Newton, a few iterations
// for piecewise-linear laws). A node whose elements have no damping is the balance of springs,
// which holds at all times: its time derivative sum(dT_k/dt) = 0 (Element::BalanceRate) gives
// the speed (index reduction; the initial twists satisfy the balance, InitialState).
void System::SolveMasslessSpeeds() {
  Eval& e = eval_;
  const int k = static_cast<int>(massless_.size());
  Eigen::MatrixXd A(k, k);
  Eigen::VectorXd r(k);
  for (int iteration = 0; iteration < 8; ++iteration) {
    A.setZero();
    r.setZero();
    for (int i = 0; i < k; ++i) {
      const int n = massless_[i];
      const double w = e.w[n], h = 1e-6 * (1.0 + std::abs(w));
      auto slope = [&](const Element& x, bool rate) {
        int other = -1;
        const double up = rate ? x.BalanceRate(e, n, w + h, other) : x.BalanceTorque(e, n, w + h, other);
        const double down = rate ? x.BalanceRate(e, n, w - h, other) : x.BalanceTorque(e, n, w - h, other);
        return (up - down) / (2 * h);
      };
      bool damped = false;
      for (int el : massless_elements_[i]) damped = damped || slope(*elements_[el], false) != 0.0;
      for (int el : massless_elements_[i]) {
        const Element& x = *elements_[el];
        int other = -1;
        r[i] += damped ? x.BalanceTorque(e, n, w, other) : x.BalanceRate(e, n, w, other);
        const double d = slope(x, !damped);
        A(i, i) += d;  // the torque depends on w_rel: -d with respect to the other flange
        if (other >= 0 && nodes_[other].massless) A(i, massless_local_[other]) -= d;
      }
    }
    // A node in the free play of every element (no stiffness, no damping) moves with the mean
    // of its neighbours.
    for (int i = 0; i < k; ++i)
      if (A.row(i).cwiseAbs().maxCoeff() == 0.0) {
        const int n = massless_[i];
        double sum = 0.0;
        int count = 0;
        for (int el : massless_elements_[i])
          for (int m : elements_[el]->Nodes())
            if (m != n && !nodes_[m].massless) sum += e.w[m], ++count;
        A(i, i) = 1.0;
        r[i] = e.w[n] - (count > 0 ? sum / count : 0.0);
      }
    const Eigen::VectorXd step = A.fullPivLu().solve(-r);
    double largest = 0.0, scale = 0.0;
    for (int i = 0; i < k; ++i) {
      if (!std::isfinite(step[i])) continue;
      e.w[massless_[i]] += step[i];
      largest = std::max(largest, std::abs(step[i]));
      scale = std::max(scale, std::abs(e.w[massless_[i]]));
    }
    if (!(largest > 1e-13 * (1.0 + scale))) break;
  }
}

// Springs without damping at a massless node must balance from the start: the node angle (and
// with it the twists of the elements on it whose start value is not given) is moved until the
// torques balance (Newton on each node in turn, a few sweeps for chains of massless nodes).
void System::BalanceMasslessTwists(double* y) {
  Eval& e = eval_;
  e.y = y;
  for (int sweep = 0; sweep < 20; ++sweep) {
    double largest = 0.0;
    for (std::size_t i = 0; i < massless_.size(); ++i) {
      const int n = massless_[i];
      auto balance = [&] {
        double sum = 0.0;
        int other = -1;
        for (int el : massless_elements_[i]) sum += elements_[el]->BalanceTorque(e, n, e.w[n], other);
        return sum;
      };
      auto shift = [&](double delta) {  // the node angle by delta: the twists of free elements
        e.phi[n] += delta;
        if (nodes_[n].s_phi >= 0) y[nodes_[n].s_phi] += delta;
        for (int el : massless_elements_[i]) {
          const Element& x = *elements_[el];
          if (x.TwistStates().empty()) continue;
          const auto nodes = x.Nodes();
          y[x.state_offset] += nodes.size() > 1 && nodes[1] == n ? delta : -delta;
        }
      };
      const double f = balance();
      const double h = 1e-7 * (1e-3 + std::abs(e.phi[n]));
      shift(h);
      const double slope = (balance() - f) / h;
      shift(-h);
      if (!(std::abs(slope) > 0)) continue;
      const double delta = -f / slope;
      shift(delta);
      largest = std::max(largest, std::abs(delta));
    }
    if (largest <= 1e-14) break;
  }
}

std::vector<double> System::InitialState(double t0) {
  DiscreteStateChanged();  // discrete state or start values change
  t_segment_ = t0;
  eval_.t = t0;
  eval_.t_segment = t0;
  eval_.initial = true;
  EvaluateSignals(signal_order_);
  std::vector<Element::InitialEquation> position, speed, holonomic;
  std::vector<int> position_owner, speed_owner, holonomic_owner;
  for (const auto& el : elements_) {
    el->InitialEquationsAt(eval_, position, speed);
    el->HolonomicRows(holonomic);
    position_owner.resize(position.size(), el->index);
    speed_owner.resize(speed.size(), el->index);
    holonomic_owner.resize(holonomic.size(), el->index);
  }
  std::vector<int> unknown(nodes_.size(), -1);
  std::vector<double> known_phi(nodes_.size(), 0.0), known_w(nodes_.size(), 0.0);
  int n_unknown = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].ground) known_phi[n] = nodes_[n].phi0;
    else unknown[n] = n_unknown++;
  }
  // Start values that are guesses (MSL fixed = false): the solution nearest to them.
  std::vector<std::pair<int, double>> position_guess, speed_guess;
  for (const auto& el : elements_) el->InitialGuesses(position_guess, speed_guess);
  auto solve = [&](std::vector<Element::InitialEquation> rows, std::vector<int> owner,
                   const std::vector<double>& known, const std::vector<std::pair<int, double>>& guesses,
                   const char* what) {
    Eigen::VectorXd guess = Eigen::VectorXd::Zero(n_unknown);
    std::vector<char> guessed(n_unknown, 0);
    for (auto [node, value] : guesses)
      if (unknown[node] >= 0) guess[unknown[node]] = value, guessed[unknown[node]] = 1;
    for (std::size_t k = 0; k < holonomic.size(); ++k) {
      rows.push_back(holonomic[k]);
      owner.push_back(holonomic_owner[k]);
    }
    Eigen::VectorXd d;
    // The residual of row i at x, and whether it is within the tolerance.
    auto residual = [&](const std::vector<Element::InitialEquation>& r_rows, const Eigen::VectorXd& x, std::size_t i,
                        double& r) {
      r = -d[static_cast<int>(i)];
      double scale = std::abs(d[static_cast<int>(i)]);
      for (auto [node, coef] : r_rows[i].row)
        if (unknown[node] >= 0) {
          r += coef * x[unknown[node]];
          scale += std::abs(coef * x[unknown[node]]);
        }
      return std::abs(r) <= 1e-8 * (1.0 + scale);
    };
    // Guesses consistent with the equations are taken as they are (the equations with the
    // guesses added have a solution); otherwise the solution nearest to them.
    if (!guesses.empty()) {
      std::vector<Element::InitialEquation> with = rows;
      for (auto [node, value] : guesses) with.push_back({{{node, 1.0}}, value});
      const Eigen::VectorXd none = Eigen::VectorXd::Zero(n_unknown);
      const Eigen::VectorXd x = MinimumNorm(with, unknown, known, n_unknown, none, std::vector<char>(n_unknown, 0), d);
      bool consistent = true;
      double r = 0.0;
      for (std::size_t i = 0; i < with.size() && consistent; ++i) consistent = residual(with, x, i, r);
      if (consistent) return x;
    }
    Eigen::VectorXd x = MinimumNorm(rows, unknown, known, n_unknown, guess, guessed, d);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      double r = 0.0;
      if (!residual(rows, x, i, r)) {
        const Element& el = *elements_[owner[i]];
        throw InputError("element '" + el.id + "' (" + el.type + "): the initial " + what +
                         " contradict the other initial values or the kinematic constraints "
                         "(residual " + FormatMessageNumber(r) +
                         "); give fewer initial values or make them consistent");
      }
    }
    return x;
  };
  Eigen::VectorXd phi = solve(position, position_owner, known_phi, position_guess, "angles");
  Eigen::VectorXd w = solve(speed, speed_owner, known_w, speed_guess, "speeds");
  start_position_ = std::move(position);
  start_speed_ = std::move(speed);
  for (const auto& row : holonomic) {
    start_position_.push_back(row);
    start_speed_.push_back({row.row, 0.0});
  }
  start_unknown_ = std::move(unknown);
  start_unknowns_ = n_unknown;
  std::vector<double> y(n_states_, 0.0);
  StartState(phi, w, y.data(), true);
  return y;
}

void System::StartState(const Eigen::VectorXd& phi, const Eigen::VectorXd& w, double* y, bool pressures) {
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].ground) {  // a Fixed at phi0 (the twists of the elements on it start from there)
      eval_.phi[n] = nodes_[n].phi0;
      eval_.w[n] = 0.0;
      continue;
    }
    const int u = start_unknown_[n];
    y[nodes_[n].s_phi] = eval_.phi[n] = phi[u];
    y[nodes_[n].s_w] = eval_.w[n] = w[u];
  }
  for (const auto& h : hnodes_)
    if (h.s_p >= 0) {
      if (pressures) y[h.s_p] = std::isnan(h.p_start) ? 1e5 : h.p_start;
      eval_.p[&h - hnodes_.data()] = y[h.s_p];
    } else {
      eval_.p[&h - hnodes_.data()] = h.p_fixed;
    }
  for (const auto& el : elements_) el->InitStates(eval_, y);
  if (!massless_.empty()) BalanceMasslessTwists(y);
}

bool System::HasInitialAccelerations() const {
  std::vector<std::pair<int, double>> acceleration;
  for (const auto& el : elements_) el->InitialAccelerations(acceleration);
  return !acceleration.empty();
}

std::string System::StartValueName(int node, bool speed) const {
  for (const auto& el : elements_) {
    const auto nodes = el->Nodes();
    if ((el->type == "Inertia" || el->type == "Mass") && !nodes.empty() && nodes[0] == node)
      return el->id + (el->type == "Mass" ? (speed ? ".v" : ".s") : (speed ? ".w" : ".phi"));
  }
  return "flange '" + nodes_[node].name + "' " + (speed ? "speed" : "angle");
}

namespace {

// The null space of the linear initial equations in the unknowns: one column per free
// unknown (a non-pivot column of the full-pivoting LU), 1 at that unknown, 0 at the other
// free ones; `free_unknown` names the free unknown of each column.
Eigen::MatrixXd StartNullSpace(const std::vector<Element::InitialEquation>& rows, const std::vector<int>& unknown,
                               int n_unknown, std::vector<int>& free_unknown) {
  free_unknown.clear();
  if (rows.empty()) {
    for (int k = 0; k < n_unknown; ++k) free_unknown.push_back(k);
    return Eigen::MatrixXd::Identity(n_unknown, n_unknown);
  }
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(static_cast<int>(rows.size()), n_unknown);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (auto [node, coef] : rows[i].row)
      if (unknown[node] >= 0) E(static_cast<int>(i), unknown[node]) += coef;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(E);
  lu.setThreshold(1e-10);
  const Eigen::MatrixXd kernel = lu.kernel();
  if (lu.rank() == n_unknown) return Eigen::MatrixXd::Zero(n_unknown, 0);
  // Eigen's kernel has the identity on the non-pivot columns, in the order of permutationQ.
  for (int c = 0; c < kernel.cols(); ++c) free_unknown.push_back(lu.permutationQ().indices()[lu.rank() + c]);
  return kernel;
}

}  // namespace

std::string System::SolveInitialAccelerations(double t, std::vector<double>& y, bool steady_state) {
  // The equations: residual = value - target, either a node acceleration or a state derivative.
  struct Equation {
    int node = -1;       ///< a node acceleration, or
    int state = -1;      ///< the derivative of a state (a spring twist)
    double target = 0.0;
    std::string what;    ///< for messages: "element 'J1' (Inertia): a = a_start = 2 rad/s^2"
    std::string unit;
  };
  std::vector<Equation> equations;
  for (const auto& el : elements_) {
    std::vector<std::pair<int, double>> acceleration;
    el->InitialAccelerations(acceleration);
    for (auto [node, a] : acceleration) {
      std::ostringstream what;
      const std::string unit = el->type == "Mass" ? " m/s^2" : " rad/s^2";
      what << "element '" << el->id << "' (" << el->type << "): the initial equation a = a_start = " << a << unit;
      equations.push_back({node, -1, a, what.str(), unit});
    }
  }
  std::vector<char> has_equation(nodes_.size(), 0);
  for (const auto& eq : equations) has_equation[eq.node] = 1;
  if (steady_state) {
    for (std::size_t n = 0; n < nodes_.size(); ++n)
      if (!nodes_[n].ground && !nodes_[n].massless && nodes_[n].J > 0 && !has_equation[n])
        equations.push_back({static_cast<int>(n), -1, 0.0,
                             "the steady-state start: der(" + StartValueName(static_cast<int>(n), true) + ") = 0", ""});
    std::vector<double> stiffness;
    for (const auto& el : elements_) {
      stiffness.assign(el->NumStates(), 0.0);
      if (el->NumStates() > 0) el->StateStiffness(stiffness.data());
      for (int k = 0; k < el->NumStates(); ++k)
        if (stiffness[k] > 0)
          equations.push_back({-1, el->state_offset + k, 0.0,
                               "the steady-state start: der(" + el->StateNames()[k] + ") = 0 of element '" + el->id +
                                   "' (" + el->type + ")", ""});
    }
  }
  if (equations.empty()) return "";

  // The unknowns: the free directions of the angles and of the speeds.
  std::vector<int> free_phi, free_w;
  const Eigen::MatrixXd Np = StartNullSpace(start_position_, start_unknown_, start_unknowns_, free_phi);
  const Eigen::MatrixXd Nw = StartNullSpace(start_speed_, start_unknown_, start_unknowns_, free_w);
  std::vector<int> unknown_node(start_unknowns_, -1);
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (start_unknown_[n] >= 0) unknown_node[start_unknown_[n]] = static_cast<int>(n);
  const int kp = static_cast<int>(Np.cols()), k = kp + static_cast<int>(Nw.cols());
  auto unknown_name = [&](int j) {
    return j < kp ? StartValueName(unknown_node[free_phi[j]], false) : StartValueName(unknown_node[free_w[j - kp]], true);
  };
  Eigen::VectorXd phi0(start_unknowns_), w0(start_unknowns_);
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (start_unknown_[n] >= 0) {
      phi0[start_unknown_[n]] = y[nodes_[n].s_phi];
      w0[start_unknown_[n]] = y[nodes_[n].s_w];
    }
  const int m = static_cast<int>(equations.size());
  std::vector<double> ydot(n_states_, 0.0), state = y;
  auto residual = [&](const Eigen::VectorXd& z, Eigen::VectorXd& r) {
    StartState(phi0 + Np * z.head(kp), w0 + Nw * z.tail(k - kp), state.data(), false);
    DiscreteStateChanged();
    if (!Evaluate(t, state.data(), ydot.data()))
      throw InputError("the initial equations on accelerations cannot be evaluated: " + error_);
    r.resize(m);
    for (int i = 0; i < m; ++i) {
      const Equation& eq = equations[i];
      r[i] = (eq.node >= 0 ? eval_.acc[eq.node] : ydot[eq.state]) - eq.target;
    }
  };
  Eigen::VectorXd z = Eigen::VectorXd::Zero(k), r, r_probe;
  residual(z, r);
  // Accepted: each equation met to 1e-8 of its scale (the target and the residual at the start
  // values); the iteration goes on while it improves, to 1e-15 of that scale.
  Eigen::VectorXd tolerance(m);
  for (int i = 0; i < m; ++i) tolerance[i] = 1e-8 * (1.0 + std::abs(equations[i].target) + std::abs(r[i]));
  auto within = [&](const Eigen::VectorXd& res, double fraction) {
    return (res.cwiseAbs().array() <= fraction * tolerance.array()).all();
  };
  auto converged = [&](const Eigen::VectorXd& res) { return within(res, 1.0); };
  auto jacobian = [&](Eigen::MatrixXd& jac) {
    jac.resize(m, k);
    for (int j = 0; j < k; ++j) {
      const double delta = 1e-6 * (1.0 + std::abs(z[j]));
      Eigen::VectorXd probe = z;
      probe[j] += delta;
      residual(probe, r_probe);
      jac.col(j) = (r_probe - r) / delta;
    }
    residual(z, r);
  };
  Eigen::MatrixXd jac;
  jacobian(jac);
  // The free values the equations involve, and whether the equations determine them.
  std::vector<int> involved;
  const double jac_max = k > 0 ? jac.cwiseAbs().maxCoeff() : 0.0;
  for (int j = 0; j < k; ++j)
    if (jac.col(j).cwiseAbs().maxCoeff() > 1e-12 * (1.0 + jac_max)) involved.push_back(j);
  auto involved_matrix = [&](const Eigen::MatrixXd& full) {
    Eigen::MatrixXd J(m, static_cast<int>(involved.size()));
    for (std::size_t c = 0; c < involved.size(); ++c) J.col(static_cast<int>(c)) = full.col(involved[c]).normalized();
    return J;
  };
  if (!involved.empty()) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(involved_matrix(jac));
    qr.setThreshold(1e-9);
    if (qr.rank() < static_cast<int>(involved.size())) {
      std::vector<std::string> names;
      for (int j : involved) names.push_back(unknown_name(j));
      std::ostringstream msg;
      msg << equations[0].what << ": the initial equations on accelerations"
          << (steady_state ? " (steady-state start)" : "") << " are under-determined: " << qr.rank()
          << " independent equation" << (qr.rank() == 1 ? "" : "s") << " for the " << involved.size()
          << " free start values " << Join(names)
          << "; fix " << (involved.size() - qr.rank() == 1 ? "one" : std::to_string(involved.size() - qr.rank()))
          << " of them (give phi_start / w_start, s_start / v_start with fixed = true)";
      throw InputError(msg.str());
    }
  }
  for (int iteration = 0; iteration < 20 && !within(r, 1e-7); ++iteration) {
    if (iteration > 0) jacobian(jac);
    if (involved.empty()) break;
    const Eigen::MatrixXd J = involved_matrix(jac);
    Eigen::VectorXd norms(static_cast<int>(involved.size()));
    for (std::size_t c = 0; c < involved.size(); ++c) norms[static_cast<int>(c)] = jac.col(involved[c]).norm();
    const Eigen::VectorXd step = J.colPivHouseholderQr().solve(-r).cwiseQuotient(norms);
    if (!step.allFinite()) break;
    Eigen::VectorXd trial = z;
    for (std::size_t c = 0; c < involved.size(); ++c) trial[involved[c]] += step[static_cast<int>(c)];
    // Damped: halve the step until the residual decreases.
    double lambda = 1.0;
    for (int halving = 0; halving < 12; ++halving) {
      residual(trial, r_probe);
      if (r_probe.norm() < r.norm()) break;
      lambda *= 0.5;
      for (std::size_t c = 0; c < involved.size(); ++c) trial[involved[c]] = z[involved[c]] + lambda * step[static_cast<int>(c)];
    }
    if (!(r_probe.norm() < r.norm())) break;
    z = trial;
    r = r_probe;
  }
  if (!converged(r)) {
    int worst = 0;
    for (int i = 0; i < m; ++i)
      if (std::abs(r[i]) / tolerance[i] > std::abs(r[worst]) / tolerance[worst]) worst = i;
    const Equation& eq = equations[worst];
    const double value = r[worst] + eq.target;
    std::ostringstream msg;
    bool untouched = true;
    for (int j : involved) untouched = untouched && jac(worst, j) == 0.0;
    msg << eq.what << " does not hold at the start: " << (eq.node >= 0 ? "a" : "the derivative") << " = " << value
        << eq.unit;
    if (untouched)
      msg << " whatever the free start values; the initial equations are over-determined: free a start value "
             "that determines it (phi_fixed / w_fixed = false, or leave phi_start / w_start out) or remove "
          << (steady_state ? "the steady-state start" : "a_start");
    else
      msg << " at best (no solution); change a_start or the start values and loads";
    throw InputError(msg.str());
  }
  residual(z, r);
  std::copy(state.begin(), state.end(), y.begin());
  DiscreteStateChanged();
  std::ostringstream account;
  account << (steady_state ? "steady-state start" : "initial accelerations") << ": " << m << " equation"
          << (m == 1 ? "" : "s") << " on " << involved.size() << " free start value" << (involved.size() == 1 ? "" : "s");
  std::vector<std::string> names;
  for (int j : involved) names.push_back(unknown_name(j));
  if (!names.empty()) account << " (" << Join(names) << ")";
  return account.str();
}

double System::SolveEquilibrium(double t, double* y, bool& found, const EquilibriumOptions& options) {
  DiscreteStateChanged();  // discrete state or start values change
  found = false;
  equilibrium_evaluations_ = 0;
  std::vector<int> unknowns;
  for (const auto& el : elements_)
    for (int k : el->TwistStates()) unknowns.push_back(el->state_offset + k);
  std::vector<int> rows;
  double j_max = 0.0;
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (!nodes_[n].ground) {
      rows.push_back(static_cast<int>(n));
      j_max = std::max(j_max, nodes_[n].J);
    }
  if (unknowns.empty() || rows.empty()) return 0.0;
  const int m = static_cast<int>(rows.size()), k = static_cast<int>(unknowns.size());
  // Residual: the torque that accelerates each node (its inertia times its acceleration; a
  // node without inertia of its own counts with a small share).
  auto residual = [&](const double* state, Eigen::VectorXd& r) {
    ++equilibrium_evaluations_;
    if (!Evaluate(t, state, nullptr)) return false;
    r.resize(m);
    for (int i = 0; i < m; ++i) {
      const int n = rows[i];
      r[i] = (nodes_[n].J + 1e-6 * j_max) * eval_.acc[n];
    }
    return true;
  };
  std::vector<double> x(y, y + n_states_);
  Eigen::VectorXd r, r_probe;
  if (!residual(x.data(), r)) return NAN;
  double torque_scale = 0.0;  // the loads: the largest force on a node at the start
  for (int i = 0; i < m; ++i) torque_scale = std::max(torque_scale, std::abs(eval_.force[rows[i]]));
  const double start = r.lpNorm<Eigen::Infinity>();
  const double goal = 1e-10 * (1.0 + torque_scale);
  if (start <= goal) {
    found = true;
    return start;
  }
  // The difference quotients of twists that share no row of the Jacobian's pattern are taken
  // from one evaluation (Curtis, Powell and Reid): a row reads one perturbed twist there, so its
  // quotient is, to the last bit, that of the twist perturbed alone. Rows a twist cannot reach
  // stay exact zeros, as their quotients (r - r) / delta are. With massless nodes every column
  // is perturbed alone: their speeds are solved together over the whole network.
  const bool group = options.group_twists && massless_.empty();
  std::vector<std::vector<int>> column_rows(k);
  std::vector<std::vector<int>> colours;  // the columns perturbed together
  {
    std::vector<int> row_of_state(n_states_, -1);
    for (int i = 0; i < m; ++i) {
      const Node& node = nodes_[rows[i]];
      row_of_state[node.s_phi] = i;
      row_of_state[node.s_w] = i;
    }
    std::vector<std::vector<char>> taken;  // per colour: the rows of its columns
    for (int j = 0; j < k; ++j) {
      std::vector<int>& reached = column_rows[j];
      if (group) {
        for (int p = jacobian_colptr_[unknowns[j]]; p < jacobian_colptr_[unknowns[j] + 1]; ++p)
          if (const int i = row_of_state[jacobian_rows_[p]]; i >= 0) reached.push_back(i);
        std::sort(reached.begin(), reached.end());
        reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
      } else {
        for (int i = 0; i < m; ++i) reached.push_back(i);
      }
      std::size_t c = 0;
      for (; c < colours.size(); ++c)
        if (group && std::none_of(reached.begin(), reached.end(), [&](int i) { return taken[c][i] != 0; }))
          break;
      if (c == colours.size()) {
        colours.emplace_back();
        taken.emplace_back(m, 0);
      }
      colours[c].push_back(j);
      for (int i : reached) taken[c][i] = 1;
    }
  }
  Eigen::MatrixXd jac(m, k);
  std::vector<double> saved(k), delta(k);
  double best = start;
  for (int iteration = 0; iteration < 8 && best > goal; ++iteration) {
    jac.setZero();
    for (const std::vector<int>& colour : colours) {
      for (int j : colour) {
        double& u = x[unknowns[j]];
        saved[j] = u;
        delta[j] = 1e-7 * (1e-3 + std::abs(u));
        u = saved[j] + delta[j];
      }
      if (!residual(x.data(), r_probe)) return NAN;
      for (int j : colour) {
        x[unknowns[j]] = saved[j];
        for (int i : column_rows[j]) jac(i, j) = (r_probe[i] - r[i]) / delta[j];
      }
    }
    const Eigen::VectorXd step = jac.colPivHouseholderQr().solve(-r);
    if (!step.allFinite()) break;
    std::vector<double> trial = x;
    for (int j = 0; j < k; ++j) trial[unknowns[j]] += step[j];
    if (!residual(trial.data(), r_probe)) return NAN;
    const double norm = r_probe.lpNorm<Eigen::Infinity>();
    if (!(norm < best)) break;
    best = norm;
    x = std::move(trial);
    r = r_probe;
  }
  // Accept only an equilibrium: the loads balanced to a small fraction of themselves.
  if (best <= 1e-6 * (1.0 + torque_scale)) {
    found = true;
    std::copy(x.begin(), x.end(), y);
    return best;
  }
  Evaluate(t, y, nullptr);
  return best;
}

int System::NodeOfPort(const std::string& port) const {
  auto it = port_node_.find(port);
  return it == port_node_.end() ? -1 : it->second;
}

namespace {

// Gram-Schmidt on the rows of a null-space basis: picks, in the order given, the coordinates
// that are independent of those picked before (at most the dimension of the basis).
class IndependentRows {
 public:
  explicit IndependentRows(Eigen::MatrixXd basis) : basis_(std::move(basis)) {}
  int dimension() const { return static_cast<int>(basis_.cols()); }
  bool full() const { return static_cast<int>(picked_.size()) >= dimension(); }
  /// True (and the row is kept) when row k adds a direction.
  bool Pick(int k) {
    if (full()) return false;
    Eigen::VectorXd v = basis_.row(k).transpose();
    const double size = v.norm();
    if (!(size > 0)) return false;
    for (const auto& q : picked_) v -= q.dot(v) * q;
    for (const auto& q : picked_) v -= q.dot(v) * q;  // twice is enough (Kahan)
    if (!(v.norm() > 1e-9 * size)) return false;
    picked_.push_back(v / v.norm());
    return true;
  }

 private:
  Eigen::MatrixXd basis_;
  std::vector<Eigen::VectorXd> picked_;
};

// A basis of the null space of the rows (restricted to the unknown nodes), n x d.
Eigen::MatrixXd NullSpace(const std::vector<Element::InitialEquation>& rows, const std::vector<int>& unknown,
                          int n_unknown) {
  if (rows.empty()) return Eigen::MatrixXd::Identity(n_unknown, n_unknown);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<int>(rows.size()), n_unknown);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (auto [node, coef] : rows[i].row)
      if (unknown[node] >= 0) A(static_cast<int>(i), unknown[node]) += coef;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  lu.setThreshold(1e-10);
  if (lu.rank() == 0) return Eigen::MatrixXd::Identity(n_unknown, n_unknown);
  if (lu.rank() == n_unknown) return Eigen::MatrixXd(n_unknown, 0);
  return lu.kernel();
}

}  // namespace

std::vector<System::NodeStart> System::StartOfFreeNodes(const double* y, const std::vector<int>& candidates,
                                                        double& inconsistency) {
  std::vector<int> unknown(nodes_.size(), -1);
  std::vector<double> known(nodes_.size(), 0.0);
  int n_unknown = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].ground) known[n] = nodes_[n].phi0;
    else unknown[n] = n_unknown++;
  }
  // What fixes angles and speeds already: the gears and the elements' own initial equations
  // (given start values, a Modelica class's fixed start values); the twists on top of them.
  eval_.y = y;
  std::vector<Element::InitialEquation> holonomic, position, speed, twists;
  for (const auto& el : elements_) {
    el->HolonomicRows(holonomic);
    el->InitialEquationsAt(eval_, position, speed);
    el->TwistRows(y, twists);
  }
  std::vector<Element::InitialEquation> fixed_angles = holonomic, fixed_speeds = holonomic;
  fixed_angles.insert(fixed_angles.end(), position.begin(), position.end());
  fixed_speeds.insert(fixed_speeds.end(), speed.begin(), speed.end());
  // Node angles consistent with the twists, nearest to those of y, the nodes that a stuck
  // brake holds in the housing moving least: the parked drive unit keeps its angle (an angle
  // sensor there reads what the simulator's reads) and the angles outboard follow the twists.
  std::vector<Element::InitialEquation> all = fixed_angles;
  all.insert(all.end(), twists.begin(), twists.end());
  Eigen::VectorXd phi0(n_unknown), D = Eigen::VectorXd::Ones(n_unknown);
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (unknown[n] >= 0) phi0[unknown[n]] = y[nodes_[n].s_phi];
  if (Evaluate(eval_.t, y, nullptr)) {
    for (const Constraint& c : eval_.constraints) {
      int moving = 0, node = -1;
      for (auto [m, coef] : c.row)
        if (unknown[m] >= 0 && coef != 0.0) ++moving, node = m;
      if (moving == 1) D[unknown[node]] = 1e-3;  // held against the housing
    }
  }
  Eigen::VectorXd d;
  const Eigen::VectorXd phi = MinimumNormScaled(all, unknown, known, n_unknown, phi0, D, d);
  inconsistency = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    double r = -d[static_cast<int>(i)];
    for (auto [node, coef] : all[i].row)
      if (unknown[node] >= 0) r += coef * phi[unknown[node]];
    inconsistency = std::max(inconsistency, std::abs(r));
  }
  IndependentRows angles(NullSpace(fixed_angles, unknown, n_unknown));
  IndependentRows speeds(NullSpace(fixed_speeds, unknown, n_unknown));
  std::vector<NodeStart> out;
  std::vector<char> seen(nodes_.size(), 0);
  for (int n : candidates) {
    if (n < 0 || seen[n] || unknown[n] < 0 || nodes_[n].massless) continue;
    seen[n] = 1;
    NodeStart s;
    s.node = n;
    s.fix_phi = angles.Pick(unknown[n]);
    s.fix_w = speeds.Pick(unknown[n]);
    s.phi = phi[unknown[n]];
    s.w = y[nodes_[n].s_w];
    if (s.fix_phi || s.fix_w) out.push_back(s);
  }
  // Free nodes no candidate reaches (reported, not fixed).
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (seen[n] || unknown[n] < 0 || nodes_[n].massless) continue;
    if (angles.Pick(unknown[n]) || speeds.Pick(unknown[n])) out.push_back({static_cast<int>(n), false, false, phi[unknown[n]], y[nodes_[n].s_w]});
  }
  return out;
}

std::vector<std::optional<std::vector<int>>> System::SpeedRows() const {
  std::vector<std::optional<std::vector<int>>> rows(n_states_);
  for (const StateNode& node : state_nodes_) {
    if (node.massless) rows[node.s_w] = std::vector<int>{};  // held: der(w) = 0
    else rows[node.s_phi] = std::vector<int>{node.s_w};
  }
  for (const auto& el : elements_)
    for (int k = 0; k < el->NumStates(); ++k) {
      const std::vector<int> speed_nodes = el->StateSpeedNodes(k);
      if (speed_nodes.empty()) continue;
      std::vector<int> row;
      bool speeds_only = true;
      for (int n : speed_nodes) {
        if (nodes_[n].ground) continue;  // at rest
        if (nodes_[n].massless) speeds_only = false;  // its speed is solved from the torques
        else row.push_back(nodes_[n].s_w);
      }
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
      if (speeds_only) rows[el->state_offset + k] = std::move(row);
    }
  return rows;
}

std::vector<double> System::AbsoluteTolerances(double absolute, double torque_tolerance, double speed_floor) const {
  std::vector<double> tolerance(n_states_, absolute);
  auto scaled = [&](double nominal) { return std::isnan(nominal) ? absolute : absolute * std::abs(nominal); };
  for (const Node& node : nodes_) {
    if (node.ground) continue;
    tolerance[node.s_phi] = scaled(node.phi_nominal);
    tolerance[node.s_w] = std::max(scaled(node.w_nominal), speed_floor);
  }
  std::vector<double> stiffness, nominal;
  for (const auto& el : elements_) {
    const int n = el->NumStates();
    if (n == 0) continue;
    nominal.assign(n, NAN);
    el->StateNominals(nominal.data());
    for (int k = 0; k < n; ++k) tolerance[el->state_offset + k] = scaled(nominal[k]);
    if (!(torque_tolerance > 0)) continue;
    stiffness.assign(n, 0.0);
    el->StateStiffness(stiffness.data());
    for (int k = 0; k < n; ++k)
      if (stiffness[k] > 0) tolerance[el->state_offset + k] = torque_tolerance / stiffness[k];
  }
  return tolerance;
}

// Every element is called in every phase until one evaluation with derivatives has shown
// which phases each element leaves to the (no-op) default.
void System::PrunePhases() {
  auto keep = [&](std::vector<Element*>& list, unsigned phase) {
    list.clear();
    for (auto& el : elements_)
      if (!(el->unused_phases & phase)) list.push_back(el.get());
  };
  keep(forces_, Element::kForcesPhase);
  keep(constraints_, Element::kConstraintsPhase);
  keep(after_solve_, Element::kAfterSolvePhase);
  keep(derivatives_, Element::kDerivativesPhase);
  MarkDirectCalls();
  phases_pruned_ = true;
}

namespace {

/// Exactly a msl::SpringDamper (a class derived from it, such as the translational spring-damper,
/// takes the virtual calls).
bool IsSpringDamper(const Element& el) { return typeid(el) == typeid(msl::SpringDamper); }
/// A StribeckFriction (final) whose Forces is SmoothOneNodeForces.
bool IsSmoothFriction(const Element& el) {
  return typeid(el) == typeid(StribeckFriction) && static_cast<const StribeckFriction&>(el).smooth_one_node_;
}

/// The virtual calls of Evaluate and the step-end readings, made directly for a SpringDamper.
msl::SpringDamper& AsSpringDamper(Element& el) { return static_cast<msl::SpringDamper&>(el); }
const msl::SpringDamper& AsSpringDamper(const Element& el) { return static_cast<const msl::SpringDamper&>(el); }

}  // namespace

void System::MarkDirectCalls() {
  auto spring_damper = [](const Element& el) { return IsSpringDamper(el) ? kSpringDamper : kVirtual; };
  forces_direct_.clear();
  for (const Element* el : forces_)
    forces_direct_.push_back(IsSmoothFriction(*el) ? kSmoothFriction : spring_damper(*el));
  derivatives_direct_.clear();
  for (const Element* el : derivatives_) derivatives_direct_.push_back(spring_damper(*el));
  reading_direct_.clear();
  for (int i : reading_elements_) {
    const Element& el = *elements_[static_cast<std::size_t>(i)];
    reading_direct_.push_back(IsSmoothFriction(el) ? kSmoothFriction : spring_damper(el));
  }
}

void System::EvaluateSignals(const std::vector<int>& order) {
  for (int i : order) {
    const Element& el = *elements_[i];
    el.Signals(eval_, &eval_.signal[el.signal_offset]);
    if (needs_signal_derivatives_)
      el.SignalDerivatives(eval_, &eval_.signal_d1[el.signal_offset], &eval_.signal_d2[el.signal_offset]);
  }
}

bool System::AtLastEvaluation(double t, const double* y) const {
  if (!cache_valid_ || t != cache_t_ || t_segment_ != cache_segment_) return false;
  // The same doubles bit for bit (memcmp, vectorised: a hit compares every state, several times
  // per step). A state of -0.0 against 0.0 is a miss, and the point is evaluated again; a NaN
  // state fails the evaluation either way.
  return std::memcmp(y, cache_y_.data(), sizeof(double) * static_cast<std::size_t>(n_states_)) == 0;
}

void System::SetKinematics(double t, const double* y) {
  cache_valid_ = false;
  Eval& e = eval_;
  ++e.point;
  e.t = t;
  e.t_segment = t_segment_;
  e.y = y;
  e.ydot = nullptr;
  double *phi = e.phi.data(), *w = e.w.data(), *force = e.force.data(), *acc = e.acc.data();
  // The nodes with states; forces and accelerations are cleared in the same loop (as a loop of
  // its own GCC makes the clearing two memset calls, which cost more than these stores). The
  // ground nodes are left alone: their angles and speeds are set for good (the constructor),
  // their accelerations stay 0 (no solve writes them), and nothing reads the torques the
  // elements add on them (a ground node has no equation), so those sums are never cleared.
  // (Nearly half of the A380-class model's nodes are ground: every housing and support.)
  for (const StateNode& node : state_nodes_) {
    const int n = node.node;
    phi[n] = y[node.s_phi];
    w[n] = y[node.s_w];
    force[n] = 0.0;
    acc[n] = 0.0;
  }
  if (!massless_.empty()) SolveMasslessSpeeds();
  for (std::size_t n = 0; n < hnodes_.size(); ++n) {
    e.p[n] = hnodes_[n].fixed ? hnodes_[n].p_fixed : y[hnodes_[n].s_p];
    e.q[n] = 0.0;
    e.cap[n] = 0.0;
  }
}

void System::KinematicRoots(double t, const double* y, double* g) {
  // At the point of the last full evaluation (CVODE's root functions at the end of a step) its
  // angles and speeds are those of y; anywhere else they are set afresh, and that evaluation is
  // no longer current.
  if (AtLastEvaluation(t, y))
    eval_.y = y;
  else
    SetKinematics(t, y);
  for (Element* el : kinematic_root_elements_) {
    el->Roots(eval_, kinematic_scratch_.data());
    for (int k = 0; k < el->NumRoots(); ++k)
      if (el->RootFromStates(k)) g[el->root_offset + k] = kinematic_scratch_[k];
  }
}

bool System::Evaluate(double t, const double* y, double* ydot) {
  // Evaluated at this very point already (CVODE's root function at the end of a step, then the
  // sampling of that step end): the elements hold its values.
  if (ydot == nullptr && cache_enabled_ && AtLastEvaluation(t, y)) {
    eval_.y = y;
    return true;
  }
  Eval& e = eval_;
  SetKinematics(t, y);
  e.ydot = ydot;
  EvaluateSignals(signal_order_before_);
  // Elements with assumed branches (HasAssumptions) may ask for the solve to be redone with
  // the consistent branch; each pass settles at least one of them.
  constexpr int kMaxPasses = 16;
  for (int pass = 0;; ++pass) {
    if (pass > 0)
      for (std::size_t n = 0; n < nodes_.size(); ++n) {
        e.force[n] = 0.0;
        e.acc[n] = 0.0;
      }
    e.n_constraints = 0;
    for (std::size_t k = 0; k < forces_.size(); ++k) {
      switch (forces_direct_[k]) {
        case kSpringDamper:
          AsSpringDamper(*forces_[k]).msl::SpringDamper::Forces(e);
          break;
        case kSmoothFriction:
          static_cast<StribeckFriction*>(forces_[k])->SmoothOneNodeForces(e);
          break;
        case kVirtual:
          forces_[k]->Forces(e);
          break;
      }
    }
    for (Element* el : constraints_) el->Constraints(e);
    if (!Solve()) return false;
    for (Element* el : after_solve_) el->AfterSolve(e);
    if (!signal_order_after_.empty()) EvaluateSignals(signal_order_after_);
    if (pass + 1 >= kMaxPasses) break;
    bool again = false;
    for (Element* el : assuming_) again = el->Reassume(e) || again;
    if (again) pattern_current_ = false;  // a branch changed: the next solve checks the pattern
    if (!again) break;
  }
  if (ydot != nullptr) {
    const StateNode* const nodes = state_nodes_.data();
    const double* const acc = e.acc.data();
    for (std::size_t k = 0; k < n_massive_state_nodes_; ++k) {
      ydot[nodes[k].s_phi] = y[nodes[k].s_w];
      ydot[nodes[k].s_w] = acc[nodes[k].node];
    }
    // A massless node's speed is the solved one; its speed state is not used (held).
    for (std::size_t k = n_massive_state_nodes_; k < state_nodes_.size(); ++k) {
      ydot[nodes[k].s_phi] = e.w[nodes[k].node];
      ydot[nodes[k].s_w] = 0.0;
    }
    for (std::size_t k = 0; k < derivatives_.size(); ++k) {
      if (derivatives_direct_[k] == kSpringDamper)
        AsSpringDamper(*derivatives_[k]).msl::SpringDamper::Derivatives(e);
      else
        derivatives_[k]->Derivatives(e);
    }
    if (!hnodes_.empty() && !HydraulicDerivatives(ydot)) return false;
    if (!phases_pruned_) PrunePhases();
  }
  // Kept for a second request at the same point: the evaluations without derivatives (a step's
  // end for its roots, then its sampling and its event). CVODE's right-hand sides (its Newton
  // iterates, the Jacobian's perturbed states) are not asked for again, so their states are
  // not copied. (SetKinematics cleared the cache.)
  if (ydot != nullptr) return true;
  cache_t_ = t;
  cache_segment_ = t_segment_;
  cache_y_.assign(y, y + n_states_);
  cache_valid_ = true;
  return true;
}

namespace {

/// Solves A x = b in place (A column-major n x n, b overwritten by x) by Gaussian elimination
/// with partial pivoting; false when a pivot is below 1e-12 of the largest entry (redundant
/// constraints), leaving A and b undefined. For the small KKT systems of the node groups
/// (a gear: 3 x 3, a gearbox with its loss: 5 x 5), where a library LU spends its time in
/// bookkeeping.
bool SmallLuSolve(double* A, double* b, int n) {
  auto at = [&](int i, int j) -> double& { return A[i + j * n]; };
  double scale = 0.0;
  for (int k = 0; k < n * n; ++k) scale = std::max(scale, std::abs(A[k]));
  const double tiny = 1e-12 * scale;
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(at(i, k)) > std::abs(at(p, k))) p = i;
    if (!(std::abs(at(p, k)) > tiny)) return false;
    if (p != k) {
      for (int j = k; j < n; ++j) std::swap(at(k, j), at(p, j));
      std::swap(b[k], b[p]);
    }
    const double inv = 1.0 / at(k, k);
    for (int i = k + 1; i < n; ++i) {
      const double f = at(i, k) * inv;
      if (f == 0.0) continue;
      for (int j = k + 1; j < n; ++j) at(i, j) -= f * at(k, j);
      b[i] -= f * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    double v = b[k];
    for (int j = k + 1; j < n; ++j) v -= at(k, j) * b[j];
    b[k] = v / at(k, k);
  }
  return true;
}

}  // namespace

// The pattern of the active constraints: owner and flange nodes of every row and column. It
// changes only at events (modes), so the grouping below is computed again only then.
void System::ConstraintSignature(std::vector<int>& signature) const {
  const Eval& e = eval_;
  signature.clear();
  signature.push_back(e.n_constraints);
  for (int k = 0; k < e.n_constraints; ++k) {
    const Constraint& c = e.constraints[k];
    signature.push_back(c.owner);
    signature.push_back(static_cast<int>(c.row.size()));
    for (const auto& [n, coef] : c.row) signature.push_back(n);
    signature.push_back(static_cast<int>(c.column.size()));
    for (const auto& [n, coef] : c.column) signature.push_back(n);
  }
}

bool System::SignatureMatches(const std::vector<int>& sig) const {
  const Eval& e = eval_;
  if (sig.empty() || sig[0] != e.n_constraints) return false;
  std::size_t at = 1;
  for (int k = 0; k < e.n_constraints; ++k) {
    const Constraint& c = e.constraints[k];
    if (at + 3 + c.row.size() + c.column.size() > sig.size()) return false;
    if (sig[at++] != c.owner || sig[at++] != static_cast<int>(c.row.size())) return false;
    for (const auto& [n, coef] : c.row)
      if (sig[at++] != n) return false;
    if (sig[at++] != static_cast<int>(c.column.size())) return false;
    for (const auto& [n, coef] : c.column)
      if (sig[at++] != n) return false;
  }
  return at == sig.size();
}

std::vector<std::vector<int>> ColourColumns(const std::vector<int>& colptr, const std::vector<int>& rows,
                                            const std::vector<char>* entry) {
  const int n = static_cast<int>(colptr.size()) - 1;
  auto present = [&](int k) { return entry == nullptr || (*entry)[static_cast<std::size_t>(k)] != 0; };
  // The columns with an entry in each row (the pattern transposed).
  std::vector<int> row_begin(static_cast<std::size_t>(n) + 1, 0), row_columns;
  for (int k = 0; k < colptr[n]; ++k)
    if (present(k)) ++row_begin[static_cast<std::size_t>(rows[k]) + 1];
  for (int i = 0; i < n; ++i) row_begin[i + 1] += row_begin[i];
  row_columns.resize(static_cast<std::size_t>(row_begin[n]));
  std::vector<int> fill(row_begin.begin(), row_begin.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int k = colptr[j]; k < colptr[j + 1]; ++k)
      if (present(k)) row_columns[static_cast<std::size_t>(fill[rows[k]]++)] = j;
  std::vector<std::vector<int>> colours;
  std::vector<int> colour(static_cast<std::size_t>(n), -1);
  std::vector<char> mark;
  for (int j = 0; j < n; ++j) {
    mark.assign(colours.size() + 1, 0);
    for (int k = colptr[j]; k < colptr[j + 1]; ++k) {
      if (!present(k)) continue;
      const int i = rows[k];
      for (int m = row_begin[i]; m < row_begin[i + 1]; ++m)
        if (const int c = colour[row_columns[m]]; c >= 0) mark[c] = 1;
    }
    int c = 0;
    while (mark[c]) ++c;
    colour[j] = c;
    if (c == static_cast<int>(colours.size())) colours.emplace_back();
    colours[c].push_back(j);
  }
  return colours;
}

const System::ModePattern* System::ModeJacobianPattern() {
  const Eval& e = eval_;
  ConstraintSignature(mode_key_);
  if (auto it = mode_patterns_.find(mode_key_); it != mode_patterns_.end())
    return it->second.colours.empty() ? nullptr : &it->second;
  // Solve's groups are those of the last evaluation unless it failed before its solve.
  if (e.n_constraints > 0 && !SignatureMatches()) return nullptr;
  if (mode_patterns_.size() >= kModePatterns) mode_patterns_.clear();
  ModePattern& pattern = mode_patterns_[mode_key_];
  pattern.key = mode_key_;
  // Hydraulic networks keep the superset's colouring: on the hydraulic PDU example a supply
  // pressure's derivative changes at the rounding level with states outside the superset
  // pattern, which each colouring adds to other entries, so the two would not give the same
  // Jacobian to the last bit (docs/performance.md, issue 30, nineteenth pass).
  if (!hnodes_.empty()) return nullptr;
  const int n_nodes = static_cast<int>(nodes_.size());
  const auto at = [](auto& v, int i) -> auto& { return v[static_cast<std::size_t>(i)]; };
  if (speed_rows_.empty()) {
    // What holds in every mode: the rows of the angles and twists (SpeedRows), the angles that
    // no law reads (a column of zeros but for its diagonal), each element's free nodes.
    speed_rows_ = SpeedRows();
    std::vector<char> read(static_cast<std::size_t>(n_nodes), 0);
    element_nodes_.assign(elements_.size(), {});
    for (std::size_t i = 0; i < elements_.size(); ++i)
      for (int n : elements_[i]->Nodes()) {
        if (elements_[i]->ReadsNodeAngles()) at(read, n) = 1;
        if (!nodes_[n].ground) element_nodes_[i].push_back(n);
      }
    unread_angle_.assign(static_cast<std::size_t>(n_states_), 0);
    node_state_.assign(static_cast<std::size_t>(n_states_), 0);
    for (int n = 0; n < n_nodes; ++n) {
      if (nodes_[n].ground) continue;
      at(node_state_, nodes_[n].s_phi) = at(node_state_, nodes_[n].s_w) = 1;
      if (!at(read, n)) at(unread_angle_, nodes_[n].s_phi) = 1;
    }
  }
  // The groups of nodes the active constraints couple: Solve's (BuildGroups, current for the
  // last evaluation's constraints), every other node a group of its own.
  std::vector<int> group_of(static_cast<std::size_t>(n_nodes), -1);
  int n_groups = 0;
  if (e.n_constraints > 0)
    for (const Group& g : groups_) {
      for (int n : g.nodes) at(group_of, n) = n_groups;
      ++n_groups;
    }
  for (int n = 0; n < n_nodes; ++n)
    if (!nodes_[n].ground && at(group_of, n) < 0) at(group_of, n) = n_groups++;
  // The cliques of AssignStates with the active constraints' groups, each as rows and the
  // columns they may depend on. A group: the accelerations of its nodes on its nodes' states
  // and on the footprints of the laws on its nodes; the states of elements (and hydraulic
  // nodes) those laws read on the same, as their derivatives may read the group's
  // accelerations or constraint torques; not the states of the nodes next to it. An element:
  // its states on its footprint and on its nodes' groups' columns.
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(n_groups)), columns(static_cast<std::size_t>(n_groups));
  for (int n = 0; n < n_nodes; ++n)
    if (!nodes_[n].ground)
      for (int s : {nodes_[n].s_phi, nodes_[n].s_w}) {
        at(rows, at(group_of, n)).push_back(s);
        at(columns, at(group_of, n)).push_back(s);
      }
  for (std::size_t i = 0; i < elements_.size(); ++i)
    for (int n : element_nodes_[i]) {
      auto& c = at(columns, at(group_of, n));
      c.insert(c.end(), footprint_states_[i].begin(), footprint_states_[i].end());
    }
  for (int g = 0; g < n_groups; ++g) {
    auto& c = at(columns, g);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    for (int s : c)
      if (!at(node_state_, s)) at(rows, g).push_back(s);
  }
  // Marks the entries (i, j) of rows x columns, but none in the column of an angle no law reads
  // and in the row of an angle or a twist only its speeds; false for an entry outside the
  // superset (an element whose constraint reaches beyond its CoupledNodes: the superset's
  // colouring stays in use).
  pattern.entry.assign(jacobian_rows_.size(), 0);
  const auto begin = jacobian_rows_.begin();
  auto mark = [&](int i, int j) {
    const auto first = begin + at(jacobian_colptr_, j), last = begin + at(jacobian_colptr_, j + 1);
    const auto it = std::lower_bound(first, last, i);
    if (it == last || *it != i) return false;
    at(pattern.entry, static_cast<int>(it - begin)) = 1;
    return true;
  };
  auto mark_all = [&](const std::vector<int>& clique_rows, const std::vector<int>& clique_columns) {
    for (int i : clique_rows) {
      if (const auto& speeds = at(speed_rows_, i)) {
        for (int j : *speeds)
          if (!at(unread_angle_, j) && std::binary_search(clique_columns.begin(), clique_columns.end(), j) &&
              !mark(i, j))
            return false;
        continue;
      }
      for (int j : clique_columns)
        if (!at(unread_angle_, j) && !mark(i, j)) return false;
    }
    return true;
  };
  for (int j = 0; j < n_states_; ++j)
    if (!mark(j, j)) return nullptr;
  for (int g = 0; g < n_groups; ++g)
    if (!mark_all(at(rows, g), at(columns, g))) return nullptr;
  std::vector<int> element_rows, element_columns;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const int n_states = elements_[i]->NumStates();
    if (n_states == 0) continue;
    element_rows.clear();
    for (int k = 0; k < n_states; ++k) element_rows.push_back(elements_[i]->state_offset + k);
    element_columns = footprint_states_[i];
    for (int n : element_nodes_[i]) {
      const auto& c = at(columns, at(group_of, n));
      element_columns.insert(element_columns.end(), c.begin(), c.end());
    }
    std::sort(element_columns.begin(), element_columns.end());  // (mark_all searches them)
    if (!mark_all(element_rows, element_columns)) return nullptr;
  }
  for (const auto& c : fixed_cliques_)  // (sorted: AssignStates)
    if (!mark_all(c, c)) return nullptr;
  pattern.colours = ColourColumns(jacobian_colptr_, jacobian_rows_, &pattern.entry);
  return &pattern;
}

void System::BuildGroups() {
  Eval& e = eval_;
  const int n_nodes = static_cast<int>(nodes_.size());
  // Groups of nodes coupled by the active constraints (union-find).
  in_constraint_.assign(n_nodes, 0);
  auto find = [&](int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  };
  for (int k = 0; k < e.n_constraints; ++k) {
    int first = -1;
    auto touch = [&](int n) {
      if (nodes_[n].ground) return;
      if (!in_constraint_[n]) {
        in_constraint_[n] = 1;
        parent_[n] = n;
      }
      if (first < 0) first = n;
      else parent_[find(n)] = find(first);
    };
    for (auto [n, c] : e.constraints[k].row) touch(n);
    for (auto [n, c] : e.constraints[k].column) touch(n);
  }
  groups_.clear();
  unconstrained_.clear();
  std::vector<int> group_of_root(n_nodes, -1);
  auto group = [&](int root) {
    if (group_of_root[root] < 0) {
      group_of_root[root] = static_cast<int>(groups_.size());
      groups_.emplace_back();
    }
    return group_of_root[root];
  };
  for (int n = 0; n < n_nodes; ++n) {
    if (nodes_[n].ground) continue;
    if (!in_constraint_[n]) {
      if (!nodes_[n].massless) unconstrained_.push_back({n, nodes_[n].J});
      continue;
    }
    groups_[group(find(n))].nodes.push_back(n);
  }
  grounded_rows_.clear();
  for (int k = 0; k < e.n_constraints; ++k) {
    int any = -1;
    for (auto [n, c] : e.constraints[k].row)
      if (!nodes_[n].ground) any = n;
    for (auto [n, c] : e.constraints[k].column)
      if (!nodes_[n].ground) any = n;
    if (any < 0) {
      grounded_rows_.push_back(k);  // between ground nodes only: its torque is undetermined
      continue;
    }
    groups_[group(find(any))].rows.push_back(k);
  }
  for (Group& g : groups_) {
    const int size = static_cast<int>(g.nodes.size() + g.rows.size());
    g.A.resize(size, size);
    g.b.resize(size);
    g.x.resize(size);
    if (size > kSmallGroup) g.lu = Eigen::PartialPivLU<Eigen::MatrixXd>(size);
    else g.lu_work.resize(size, size);
    // The Schur complement path needs the inertia of every node of the group.
    g.schur = size <= kSmallGroup;
    for (int n : g.nodes) g.schur = g.schur && nodes_[n].J > 0;
    if (!g.schur) continue;
    for (std::size_t i = 0; i < g.nodes.size(); ++i) local_[g.nodes[i]] = static_cast<int>(i);
    g.inverse_J.clear();
    for (int n : g.nodes) g.inverse_J.push_back(1.0 / nodes_[n].J);
    auto entries = [&](const ConstraintEntries& list, std::vector<int>& begin,
                       std::vector<int>& entry, std::vector<int>& local) {
      for (std::size_t p = 0; p < list.size(); ++p)
        if (!nodes_[list[p].first].ground) {
          entry.push_back(static_cast<int>(p));
          local.push_back(local_[list[p].first]);
        }
      begin.push_back(static_cast<int>(entry.size()));
    };
    g.column_begin.assign(1, 0);
    g.row_begin.assign(1, 0);
    g.column_entry.clear();
    g.column_local.clear();
    g.row_entry.clear();
    g.row_local.clear();
    for (int k : g.rows) {
      entries(e.constraints[k].column, g.column_begin, g.column_entry, g.column_local);
      entries(e.constraints[k].row, g.row_begin, g.row_entry, g.row_local);
    }
    for (int n : g.nodes) local_[n] = -1;
  }
  pair_groups_.clear();
  other_groups_.clear();
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    const Group& g = groups_[i];
    if (g.schur && g.nodes.size() == 2 && g.rows.size() == 1 && g.column_begin[1] == 2 && g.row_begin[1] == 2) {
      PairGroup p;
      for (int k = 0; k < 2; ++k) {
        p.node[k] = g.nodes[k];
        p.inverse_J[k] = g.inverse_J[k];
        p.column_entry[k] = g.column_entry[k];
        p.column_local[k] = g.column_local[k];
        p.row_entry[k] = g.row_entry[k];
        p.row_local[k] = g.row_local[k];
      }
      p.row = g.rows[0];
      p.group = static_cast<int>(i);
      pair_groups_.push_back(p);
    } else {
      other_groups_.push_back(static_cast<int>(i));
    }
  }
}

// M acc - C lambda = F, R acc = rhs with M = diag(J) > 0: acc = M^-1 (F + C lambda) and the
// constraint torques from the small system (R M^-1 C) lambda = rhs - R M^-1 F (m x m, the
// number of constraints of the group: 1 for a gear, 2 for a gearbox with its load loss).
// False when that system is singular (redundant constraints): the caller solves the full KKT.
bool System::SolveSchur(Group& g) {
  Eval& e = eval_;
  const int nn = static_cast<int>(g.nodes.size()), m = static_cast<int>(g.rows.size());
  double* acc0 = g.x.data();        // M^-1 F, then the accelerations
  double* column = g.b.data();      // M^-1 C_k, scattered over the group's nodes
  double* S = g.lu_work.data();     // m x m, column-major
  double* r = g.x.data() + nn;      // right-hand side, then lambda
  const double* inverse_J = g.inverse_J.data();
  for (int i = 0; i < nn; ++i) acc0[i] = e.force[g.nodes[i]] * inverse_J[i];
  for (int k = 0; k < m; ++k) {
    const auto* ck = e.constraints[g.rows[k]].column.begin();
    for (int i = 0; i < nn; ++i) column[i] = 0.0;
    for (int p = g.column_begin[k]; p < g.column_begin[k + 1]; ++p) {
      const int i = g.column_local[p];
      column[i] += ck[g.column_entry[p]].second * inverse_J[i];
    }
    for (int j = 0; j < m; ++j) {
      const auto* rj = e.constraints[g.rows[j]].row.begin();
      double sum = 0.0;
      for (int p = g.row_begin[j]; p < g.row_begin[j + 1]; ++p) sum += rj[g.row_entry[p]].second * column[g.row_local[p]];
      S[j + k * m] = sum;
    }
  }
  for (int j = 0; j < m; ++j) {
    const Constraint& cj = e.constraints[g.rows[j]];
    const auto* rj = cj.row.begin();
    double v = cj.rhs;
    for (int p = g.row_begin[j]; p < g.row_begin[j + 1]; ++p) v -= rj[g.row_entry[p]].second * acc0[g.row_local[p]];
    r[j] = v;
  }
  if (!SmallLuSolve(S, r, m)) return false;
  for (int k = 0; k < m; ++k) {
    const double lambda = r[k];
    Constraint& ck = e.constraints[g.rows[k]];
    ck.lambda = lambda;
    const auto* column_k = ck.column.begin();
    for (int p = g.column_begin[k]; p < g.column_begin[k + 1]; ++p) {
      const int i = g.column_local[p];
      acc0[i] += column_k[g.column_entry[p]].second * lambda * inverse_J[i];
    }
  }
  for (int i = 0; i < nn; ++i) e.acc[g.nodes[i]] = acc0[i];
  return true;
}

// SolveSchur for one constraint (a gear, a tie: most groups), the same operations in the same
// order as the general loops: the column of the constraint scattered into the group's nodes,
// the 1 x 1 Schur complement and its right-hand side, the multiplier, the accelerations. Written
// out with the group's arrays in locals, the general version spends more on its loops (and a
// memset per constraint) than on the arithmetic.
bool System::SolveSchurOne(Group& g) {
  Eval& e = eval_;
  const int nn = static_cast<int>(g.nodes.size());
  const double* const inverse_J = g.inverse_J.data();
  const int* const nodes = g.nodes.data();
  const double* const force = e.force.data();
  Constraint& c = e.constraints[g.rows[0]];
  const std::pair<int, double>* const ck = c.column.begin();
  const std::pair<int, double>* const rk = c.row.begin();
  const int *const column_entry = g.column_entry.data(), *const column_local = g.column_local.data();
  const int *const row_entry = g.row_entry.data(), *const row_local = g.row_local.data();
  const int column_end = g.column_begin[1], row_end = g.row_begin[1];
  double* const acc0 = g.x.data();
  double* const column = g.b.data();
  for (int i = 0; i < nn; ++i) {
    acc0[i] = force[nodes[i]] * inverse_J[i];
    column[i] = 0.0;
  }
  for (int p = 0; p < column_end; ++p) {
    const int i = column_local[p];
    column[i] += ck[column_entry[p]].second * inverse_J[i];
  }
  double s = 0.0;
  for (int p = 0; p < row_end; ++p) s += rk[row_entry[p]].second * column[row_local[p]];
  double v = c.rhs;
  for (int p = 0; p < row_end; ++p) v -= rk[row_entry[p]].second * acc0[row_local[p]];
  if (!(std::abs(s) > 1e-12 * std::max(0.0, std::abs(s)))) return false;
  const double lambda = v / s;
  c.lambda = lambda;
  for (int p = 0; p < column_end; ++p) {
    const int i = column_local[p];
    acc0[i] += ck[column_entry[p]].second * lambda * inverse_J[i];
  }
  double* const acc = e.acc.data();
  for (int i = 0; i < nn; ++i) acc[nodes[i]] = acc0[i];
  return true;
}

// SolveSchurOne's loops for a PairGroup, unrolled, on locals (nothing reads the group's arrays
// after a solve): the same operations in the same order, so the same doubles.
inline bool System::SolvePair(const PairGroup& p) {
  Eval& e = eval_;
  const double* const force = e.force.data();
  Constraint& c = e.constraints[p.row];
  const std::pair<int, double>* const ck = c.column.begin();
  const std::pair<int, double>* const rk = c.row.begin();
  double acc0[2] = {force[p.node[0]] * p.inverse_J[0], force[p.node[1]] * p.inverse_J[1]};
  double column[2] = {0.0, 0.0};
  const int cl0 = p.column_local[0], cl1 = p.column_local[1], rl0 = p.row_local[0], rl1 = p.row_local[1];
  const double c0 = ck[p.column_entry[0]].second, c1 = ck[p.column_entry[1]].second;
  const double r0 = rk[p.row_entry[0]].second, r1 = rk[p.row_entry[1]].second;
  column[cl0] += c0 * p.inverse_J[cl0];
  column[cl1] += c1 * p.inverse_J[cl1];
  double s = 0.0;
  s += r0 * column[rl0];
  s += r1 * column[rl1];
  double v = c.rhs;
  v -= r0 * acc0[rl0];
  v -= r1 * acc0[rl1];
  if (!(std::abs(s) > 1e-12 * std::max(0.0, std::abs(s)))) return false;
  const double lambda = v / s;
  c.lambda = lambda;
  acc0[cl0] += c0 * lambda * p.inverse_J[cl0];
  acc0[cl1] += c1 * lambda * p.inverse_J[cl1];
  double* const acc = e.acc.data();
  acc[p.node[0]] = acc0[0];
  acc[p.node[1]] = acc0[1];
  return true;
}

bool System::Solve() {
  Eval& e = eval_;
  const int n_nodes = static_cast<int>(nodes_.size());
  if (e.n_constraints == 0) {
    for (int n = 0; n < n_nodes; ++n)
      if (!nodes_[n].ground && !nodes_[n].massless) e.acc[n] = e.force[n] / nodes_[n].J;
    return true;
  }
  // The groups follow the pattern of the active constraints, which changes only with the
  // discrete state (pattern_current_): between events it is not compared again.
  if (!pattern_current_) {
    if (!SignatureMatches()) {
      ConstraintSignature(signature_);
      BuildGroups();
    }
    pattern_current_ = cache_enabled_;
  }
  assert(SignatureMatches());
  for (const auto& [n, J] : unconstrained_) e.acc[n] = e.force[n] / J;
  for (int k : grounded_rows_) e.constraints[k].lambda = 0.0;
  for (const PairGroup& p : pair_groups_)
    if (!SolvePair(p) && !SolveGroup(groups_[p.group])) return false;
  for (int i : other_groups_)
    if (!SolveGroup(groups_[i])) return false;
  return true;
}

bool System::SolveGroup(Group& g) {
  Eval& e = eval_;
  const int nn = static_cast<int>(g.nodes.size()), m = static_cast<int>(g.rows.size());
  if (g.schur && (m == 1 ? SolveSchurOne(g) : SolveSchur(g))) return true;
  for (int i = 0; i < nn; ++i) local_[g.nodes[i]] = i;
  g.A.setZero();
  for (int i = 0; i < nn; ++i) {
    g.A(i, i) = nodes_[g.nodes[i]].J;
    g.b[i] = e.force[g.nodes[i]];
  }
  for (int j = 0; j < m; ++j) {
    const Constraint& c = e.constraints[g.rows[j]];
    for (auto [n, coef] : c.column)
      if (!nodes_[n].ground) g.A(local_[n], nn + j) -= coef;
    for (auto [n, coef] : c.row)
      if (!nodes_[n].ground) g.A(nn + j, local_[n]) += coef;
    g.b[nn + j] = c.rhs;
  }
  // Partial pivoting suffices unless the constraints are redundant (a tiny pivot).
  bool solved = false;
  if (nn + m <= kSmallGroup) {
    g.lu_work = g.A;
    g.x = g.b;
    solved = SmallLuSolve(g.lu_work.data(), g.x.data(), nn + m);
  } else {
    g.lu.compute(g.A);
    const auto& lu = g.lu.matrixLU();
    double pivot_min = std::numeric_limits<double>::infinity(), pivot_max = 0.0;
    for (int i = 0; i < nn + m; ++i) {
      pivot_min = std::min(pivot_min, std::abs(lu(i, i)));
      pivot_max = std::max(pivot_max, std::abs(lu(i, i)));
    }
    if (pivot_min > 1e-12 * pivot_max) {
      g.x = g.lu.solve(g.b);
      solved = true;
    }
  }
  if (!solved) {
    // Redundant constraints (several stuck elements on one rigid shaft): the accelerations
    // are unique, the split of the constraint torques is not; take the minimum-norm split.
    Eigen::FullPivLU<Eigen::MatrixXd> full(g.A);
    if (full.isInvertible()) {
      g.x = full.solve(g.b);
    } else {
      g.x = g.A.completeOrthogonalDecomposition().solve(g.b);
      const Eigen::MatrixXd kernel = full.kernel();
      double worst = 0.0;
      for (int c = 0; c < kernel.cols(); ++c)
        worst = std::max(worst, kernel.col(c).head(nn).norm() / kernel.col(c).norm());
      const double residual = (g.A * g.x - g.b).norm();
      if (worst > 1e-8 || residual > 1e-8 * (1.0 + g.b.norm())) {
        std::vector<std::string> names;
        for (int n : g.nodes) names.push_back(nodes_[n].name);
        std::vector<std::string> owners;
        for (int k : g.rows) owners.push_back(elements_[e.constraints[k].owner]->id);
        error_element_ = owners.empty() ? "" : owners.front();
        error_ = "the accelerations of the flanges " + Join(names) +
                 " are not determined (singular system of the constraints of " + Join(owners) +
                 " at t = " + FormatMessageNumber(e.t) +
                 "); add inertia to these flanges or remove redundant couplings";
        for (int n : g.nodes) local_[n] = -1;
        return false;
      }
    }
  }
  for (int i = 0; i < nn; ++i) e.acc[g.nodes[i]] = g.x[i];
  for (int j = 0; j < m; ++j) e.constraints[g.rows[j]].lambda = g.x[nn + j];
  for (int n : g.nodes) local_[n] = -1;
  return true;
}

bool System::ProjectSpeeds(double* y) {
  // Minimum kinetic-energy change such that every velocity-level constraint holds:
  // min 1/2 (w' - w)^T J (w' - w)  s.t.  G w' = 0.
  Eval& e = eval_;
  std::vector<int> rows;
  for (int k = 0; k < e.n_constraints; ++k)
    if (e.constraints[k].velocity_level) rows.push_back(k);
  if (rows.empty()) return true;
  std::vector<int> node_list;
  for (int k : rows) {
    for (auto [n, c] : e.constraints[k].row)
      if (!nodes_[n].ground && local_[n] < 0) {
        local_[n] = static_cast<int>(node_list.size());
        node_list.push_back(n);
      }
  }
  const int nn = static_cast<int>(node_list.size()), m = static_cast<int>(rows.size());
  double j_max = 0.0;
  for (int n : node_list) j_max = std::max(j_max, nodes_[n].J);
  // W: each node's inertia with 1e-9 of the largest added (a node without inertia stays determined).
  auto weight = [&](int n) { return nodes_[n].J + 1e-9 * (j_max + 1e-12); };
  // The groups of nodes coupled by the rows: the problem separates into one small KKT system
  // per group. A row on ground nodes alone constrains no speed and belongs to no group. (In a
  // group the nodes and the rows keep their order.)
  UnionFind coupled(nn);
  std::vector<int> row_node(static_cast<std::size_t>(m), -1);  // a node of each row (local index)
  for (int j = 0; j < m; ++j)
    for (auto [n, c] : e.constraints[rows[j]].row) {
      if (nodes_[n].ground) continue;
      if (row_node[j] < 0) row_node[j] = local_[n];
      else coupled.Unite(local_[n], row_node[j]);
    }
  std::vector<std::vector<int>> group_nodes, group_rows;  // local node indices, indices into rows
  std::vector<int> group_of_root(static_cast<std::size_t>(nn), -1);
  auto group_of = [&](int i) {
    int& g = group_of_root[coupled.Find(i)];
    if (g < 0) {
      g = static_cast<int>(group_nodes.size());
      group_nodes.emplace_back();
      group_rows.emplace_back();
    }
    return g;
  };
  for (int i = 0; i < nn; ++i) group_nodes[group_of(i)].push_back(i);
  for (int j = 0; j < m; ++j)
    if (row_node[j] >= 0) group_rows[group_of(row_node[j])].push_back(j);
  std::vector<double> w_new(static_cast<std::size_t>(nn));
  std::vector<int> in_group(static_cast<std::size_t>(nn), -1);  // local index -> index in its group
  std::vector<double> coefficient;
  for (std::size_t g = 0; g < group_nodes.size(); ++g) {
    const std::vector<int>& members = group_nodes[g];
    const int gn = static_cast<int>(members.size()), gm = static_cast<int>(group_rows[g].size());
    for (int a = 0; a < gn; ++a) in_group[members[a]] = a;
    if (gm == 1) {
      // One row g.w' = v (nearly every group: a gear or a stuck element between two nodes):
      // w' = w + W^-1 g lambda with lambda = (v - g.w) / (g^T W^-1 g).
      const Constraint& c = e.constraints[rows[group_rows[g][0]]];
      coefficient.assign(static_cast<std::size_t>(gn), 0.0);
      for (auto [n, coef] : c.row)
        if (!nodes_[n].ground) coefficient[in_group[local_[n]]] += coef;  // (a node twice: one entry)
      double gw = 0.0, gwg = 0.0;
      for (int a = 0; a < gn; ++a) {
        const int n = node_list[members[a]];
        gw += coefficient[a] * y[nodes_[n].s_w];
        gwg += coefficient[a] * coefficient[a] / weight(n);
      }
      const double lambda = gwg > 0.0 ? (c.velocity_rhs - gw) / gwg : 0.0;  // (no row left: no change)
      for (int a = 0; a < gn; ++a) {
        const int n = node_list[members[a]];
        w_new[members[a]] = y[nodes_[n].s_w] + coefficient[a] * lambda / weight(n);
      }
      continue;
    }
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(gn + gm, gn + gm);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(gn + gm);
    for (int a = 0; a < gn; ++a) {
      const int n = node_list[members[a]];
      K(a, a) = weight(n);
      b[a] = weight(n) * y[nodes_[n].s_w];
    }
    for (int r = 0; r < gm; ++r) {
      const Constraint& c = e.constraints[rows[group_rows[g][r]]];
      b[gn + r] = c.velocity_rhs;
      for (auto [n, coef] : c.row)
        if (!nodes_[n].ground) {
          const int a = in_group[local_[n]];
          K(gn + r, a) += coef;
          K(a, gn + r) += coef;
        }
    }
    // Complete orthogonal decomposition: redundant constraints (several stuck elements on one
    // rigid shaft) give the minimum-norm multipliers and still the unique speeds.
    const Eigen::VectorXd x = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(K).solve(b);
    for (int a = 0; a < gn; ++a) w_new[members[a]] = x[a];
  }
  double kinetic_change = 0.0;
  for (int i = 0; i < nn; ++i) {
    double& w = y[nodes_[node_list[i]].s_w];
    kinetic_change += 0.5 * nodes_[node_list[i]].J * (w * w - w_new[i] * w_new[i]);
    w = w_new[i];
    local_[node_list[i]] = -1;
  }
  impulsive_loss_ += std::max(kinetic_change, 0.0);
  return true;
}

System::EnergyState System::Energy() const {
  EnergyState s;
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    s.kinetic += 0.5 * nodes_[n].J * eval_.w[n] * eval_.w[n];
  for (const auto& el : elements_) {
    s.potential += el->StoredEnergy(eval_);
    s.loss_power += el->LossPower(eval_);
    s.source_power += el->SourcePower(eval_);
  }
  return s;
}

double System::StepEndReadings(std::vector<double>& loss, std::vector<double>& tau, double& lowest) const {
  if (loss.size() != elements_.size()) loss.assign(elements_.size(), 0.0);
  if (tau.size() != elements_.size()) tau.assign(elements_.size(), NAN);
  double scale = 0.0, low = INFINITY;
  for (std::size_t k = 0; k < reading_elements_.size(); ++k) {
    const auto i = static_cast<std::size_t>(reading_elements_[k]);
    const Element& el = *elements_[i];
    double p;
    if (reading_direct_[k] == kSpringDamper) {
      const msl::SpringDamper& sd = AsSpringDamper(el);
      p = sd.msl::SpringDamper::LossPower(eval_);
      scale += std::abs(p) + std::abs(sd.msl::SpringDamper::SourcePower(eval_));
      tau[i] = sd.msl::SpringDamper::PeakTorque(eval_);
    } else if (reading_direct_[k] == kSmoothFriction) {  // (final: the calls are direct)
      const StribeckFriction& f = static_cast<const StribeckFriction&>(el);
      p = f.LossPower(eval_);
      scale += std::abs(p) + std::abs(f.SourcePower(eval_));
      tau[i] = f.PeakTorque(eval_);
    } else {
      p = el.LossPower(eval_);
      scale += std::abs(p) + std::abs(el.SourcePower(eval_));
      tau[i] = el.PeakTorque(eval_);
    }
    loss[i] = p;
    low = p < low ? p : low;
  }
  lowest = low;
  return scale;
}

bool System::ReadingsAsDeclared() const {
  for (const auto& el : elements_)
    if (!el->HasReadings() &&
        !(std::isnan(el->PeakTorque(eval_)) && el->LossPower(eval_) == 0.0 && el->SourcePower(eval_) == 0.0))
      return false;
  return true;
}

void System::Roots(double* g) const {
  for (const Element* el : root_elements_) el->Roots(eval_, g + el->root_offset);
}

bool System::RootsWithoutSolve(double t, const double* y, double* g) {
  for (std::size_t i = 0; i < root_elements_.size(); ++i)
    if (roots_after_solve_[i] || root_elements_[i]->RootsNeedSolve()) return false;
  // What Evaluate computes before the forces, which is all these roots read.
  SetKinematics(t, y);
  EvaluateSignals(signal_order_before_);
  Roots(g);
  return true;
}

void System::RootDirections(int* direction) const {
  for (const auto& el : elements_)
    if (el->NumRoots() > 0) {
      for (int k = 0; k < el->NumRoots(); ++k) direction[el->root_offset + k] = 0;
      el->RootDirections(direction + el->root_offset);
    }
}

double System::NextTimeEvent(double t) const {
  double next = INFINITY;
  for (const auto& el : elements_) next = std::min(next, el->NextTimeEvent(t));
  return next;
}

bool System::HandleEvent(double t, double* y, bool initial, std::vector<std::string>* changes,
                         std::vector<std::string>* changed_elements, const int* root_info) {
  // The modes change between the evaluations of the event iteration: no cache in here, and
  // every solve checks the constraints' pattern (Solve sets pattern_current_ only while the
  // cache is enabled).
  DiscreteStateChanged();
  cache_enabled_ = false;
  struct Restore {
    bool& flag;
    ~Restore() { flag = true; }
  } restore{cache_enabled_};
  t_segment_ = t;
  if (root_info != nullptr)
    for (auto& el : elements_)
      for (int k = 0; k < el->NumRoots(); ++k)
        if (root_info[el->root_offset + k] != 0) el->MarkRootFired(k);
  eval_.initial = initial;
  std::vector<std::string> before;
  for (const auto& el : elements_) before.push_back(el->ModeText());
  if (!Evaluate(t, y, nullptr)) return false;
  for (auto& el : elements_)
    if (el->IsSwitching()) el->PrepareEvent(eval_);
  bool converged = false;
  // An element that alternates between two modes is settled after kMaxFixes switches (its
  // friction torque sits at its capacity within roundoff).
  constexpr int kMaxFixes = 8;
  std::vector<int> fixes(elements_.size(), 0);
  std::vector<char> settled(elements_.size(), 0);
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (!Evaluate(t, y, nullptr)) return false;
    if (!ProjectSpeeds(y)) return false;
    if (!Evaluate(t, y, nullptr)) return false;
    Element* worst = nullptr;
    double worst_violation = 0.0;
    for (auto& el : elements_) {
      if (!el->IsSwitching() || settled[el->index]) continue;
      const double v = el->Violation(eval_);
      if (v > worst_violation) {
        worst_violation = v;
        worst = el.get();
      }
    }
    if (worst == nullptr) {
      converged = true;
      break;
    }
    if (++fixes[worst->index] > kMaxFixes) {
      worst->Settle(eval_);
      settled[worst->index] = 1;
      continue;
    }
    worst->Fix(eval_);
  }
  eval_.initial = false;
  if (!converged) {
    error_ = "the friction modes found no consistent combination at t = " + FormatMessageNumber(t) +
             " after 200 switches";
    return false;
  }
  if (!Evaluate(t, y, nullptr)) return false;
  for (auto& el : elements_) el->EventStates(eval_, y);
  if (!Evaluate(t, y, nullptr)) return false;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const std::string after = elements_[i]->ModeText();
    if (after != before[i]) {
      if (changes) changes->push_back(before[i] + " -> " + after);
      if (changed_elements) changed_elements->push_back(elements_[i]->id);
    }
  }
  return true;
}

bool System::NeedsRestart(const int* root_info) const {
  for (const auto& el : elements_)
    for (int k = 0; k < el->NumRoots(); ++k)
      if (root_info[el->root_offset + k] != 0 && el->RootRestarts(k)) return true;
  return false;
}

bool System::HandleContinuousRoots(double t, const double* y, const int* root_info) {
  // The elements see the state of (t, y): the last evaluation when it was there (the step end
  // just sampled), else a new one; then their discrete variables change, and the next
  // Evaluate at (t, y) evaluates it afresh.
  if (!Evaluate(t, y, nullptr)) return false;
  for (auto& el : elements_)
    for (int k = 0; k < el->NumRoots(); ++k)
      if (root_info[el->root_offset + k] != 0) el->ContinuousRoot(k, eval_);
  DiscreteStateChanged();
  return true;
}

void System::AfterEventRow() {
  DiscreteStateChanged();  // discrete state or start values change
  for (auto& el : elements_) {
    el->AfterEventRow();
    el->ClearFired();
  }
}

void System::Outputs(double* out) const {
  for (std::size_t i = 0; i < elements_.size(); ++i)
    elements_[i]->Outputs(eval_, out + output_offset_[i]);
}

// --- Hydraulic nodes -------------------------------------------------------------------------
// Connected hydraulic ports form a node with one pressure p. A source (PressureSource, Tank)
// fixes p; otherwise p is a state of the compressible volumes attached (Volume, the chambers of
// a DifferentialCylinder): with capacitance C = sum(V_i/E_i),
//   dp/dt = sum(V_flow into the node) / C,
// where an element whose volume changes (a chamber V0 + A*s) adds -dV/dt to the flows. Lines and
// orifices are incompressible as in HighLift.Hydraulics, so a node without a volume or source
// would be algebraic: it is rejected with a message that names it.

void System::BuildHydraulicNodes(const Network& network) {
  std::map<std::string, int> index;
  for (const auto& el : elements_)
    for (const auto& port : el->HydraulicPorts()) {
      index[el->id + "." + port] = static_cast<int>(hydraulic_ports_.size());
      hydraulic_ports_.push_back(el->id + "." + port);
    }
  if (hydraulic_ports_.empty()) return;
  UnionFind ports(static_cast<int>(hydraulic_ports_.size()));
  for (const auto& c : network.connections()) {
    auto ia = index.find(c.a.ToString()), ib = index.find(c.b.ToString());
    if (ia == index.end() && ib == index.end()) continue;
    if (ia == index.end() || ib == index.end())
      throw InputError("connection " + c.a.ToString() + " - " + c.b.ToString() +
                       ": a hydraulic port can only be connected to a hydraulic port");
    ports.Unite(ia->second, ib->second);
  }
  std::map<int, int> root_to_node;
  std::vector<int> port_node(hydraulic_ports_.size());
  std::vector<std::vector<std::string>> members;
  for (std::size_t k = 0; k < hydraulic_ports_.size(); ++k) {
    const int r = ports.Find(static_cast<int>(k));
    auto it = root_to_node.find(r);
    if (it == root_to_node.end()) {
      it = root_to_node.emplace(r, static_cast<int>(hnodes_.size())).first;
      HydraulicNode n;
      n.name = hydraulic_ports_[k];
      hnodes_.push_back(n);
      members.emplace_back();
    }
    port_node[k] = it->second;
    members[it->second].push_back(hydraulic_ports_[k]);
  }
  for (auto& el : elements_) {
    if (el->HydraulicPorts().empty()) continue;
    el->BindHydraulic([&](const std::string& port) { return port_node[index.at(el->id + "." + port)]; });
    el->DeclareHydraulic(hnodes_);
  }
  for (std::size_t n = 0; n < hnodes_.size(); ++n)
    if (!hnodes_[n].fixed && !hnodes_[n].has_volume)
      throw InputError("hydraulic node of " + Join(members[n]) +
                       " has no volume and no source, so its pressure is undetermined; connect a "
                       "Volume (V = the line volume, e.g. 1e-5 m^3) or a PressureSource/Tank there");
  std::sort(hydraulic_ports_.begin(), hydraulic_ports_.end());
}

bool System::HydraulicDerivatives(double* ydot) {
  for (std::size_t n = 0; n < hnodes_.size(); ++n) {
    const HydraulicNode& h = hnodes_[n];
    if (h.s_p < 0) continue;
    if (!(eval_.cap[n] > 0.0)) {
      error_ = "hydraulic node '" + h.name + "' has no positive capacitance at t = " +
               FormatMessageNumber(eval_.t) + "; check the volumes attached to it";
      return false;
    }
    ydot[h.s_p] = eval_.q[n] / eval_.cap[n];
  }
  return true;
}

}  // namespace highlift::sim::detail
