// The state shared by the connectivity encoder and decoder: the "front" of open gates.
//
// The coder grows the decoded region triangle by triangle. A gate is a directed edge a->b of a
// decoded triangle whose other side has not been visited. Gates are kept in per-vertex lists
// (gates leaving / entering each vertex, newest first) and on a stack that fixes the traversal
// order. The encoder and the decoder drive this structure with the same operations in the same
// order, so their states stay identical and every coded symbol can use it as context.
//
// Gates are never reused: closing one only clears its flag, and the lists drop closed gates when
// they are next walked (each gate leaves each list once), so opening and closing cost a few stores.
// The encoder also compacts the gates between steps (MakeRoom), which bounds its memory by the
// front instead of the mesh; the decoder, whose speed matters more, does not.
#ifndef O3DGC_SRC_CONNECTIVITY_FRONT_H_
#define O3DGC_SRC_CONNECTIVITY_FRONT_H_

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "arithmetic_coder.h"
#include "entropy.h"

namespace o3dgc {

// What happens at a gate, one multi-symbol decision per gate (contexts from Front::Look): nothing
// (the gate is a boundary, it closes), or a triangle attaches whose third vertex is new, the
// right or the left candidate, or another earlier vertex (then coded as a back reference, or from
// format 1.1 on as a walk along the front when one reaches it).
enum GateOutcome : int {
  kGateClose = 0,
  kGateNew = 1,
  kGateRight = 2,
  kGateLeft = 3,
  kGateOther = 4
};
constexpr int kGateOutcomes = 5;
using GateModel = SymbolModelN<8>;

// Gate contexts: format 1.0 has 64 (which candidates exist, degree of a >= 5, degree of b up to
// 7); format 1.1 has 1280 (which candidates exist, degrees of a and of b up to 7, the previous
// gate outcome). See Front::Look.
constexpr int kGateContexts10 = 64;
constexpr int kGateContexts11 = 4 * 8 * 8 * kGateOutcomes;
// Format 1.1: the most steps a walk along the front may take to reach an "other" vertex.
constexpr uint32_t kMaxWalkSteps = 64;

// `minor`: the stream's format minor version (0 or 1), which decides how gates are coded.
struct ConnectivityModels {
  explicit ConnectivityModels(uint32_t minor)
      : rich(minor >= 1),
        gate(rich ? kGateContexts11 : kGateContexts10, GateModel(kGateOutcomes)) {}
  const bool rich;  // format 1.1: the 1280 gate contexts and walks
  BitModel more_components;
  BitModel start_new;
  EGModel start_ref;
  std::vector<GateModel> gate;
  EGModel other_ref;
  BitModel flip;
  EGModel copies;
  BitModel copy_flip;
  EGModel extra_count;
  // Format 1.1, after kGateOther: whether a walk reaches the vertex, its side, its steps - 2.
  BitModel walk;
  BitModel walk_side;
  EGModel walk_steps;
};

// The vertex ranges of the parts the front codes one after another, kept alike by the encoder and
// the decoder: part k's vertices are the ids from the end of part k - 1 up to its own end, unless
// a triangle uses vertices of two parts (a part's first triangle reuses an earlier vertex, a back
// reference reaches below the part's first vertex, or there are extra triangles); then there are
// none. (A walk stays on the front, which holds the current part's gates only: it is empty when a
// part ends.)
class ComponentEnds {
 public:
  // A part starts; `num_vertices` vertices are coded before it.
  O3DGC_NOINLINE void StartPart(uint32_t num_vertices) {
    if (started_) ends_.push_back(num_vertices);
    started_ = true;
    start_ = num_vertices;
  }
  // A triangle of the current part uses the earlier vertex v.
  void UseEarlier(uint32_t v) { shared_ |= v < start_; }
  void Share() { shared_ = true; }
  // After the last part, `num_vertices` in all: one past each part's last vertex id, or nothing.
  std::vector<uint32_t> Finish(uint32_t num_vertices) {
    if (shared_) return {};
    if (started_) ends_.push_back(num_vertices);
    return std::move(ends_);
  }

 private:
  std::vector<uint32_t> ends_;
  uint32_t start_ = 0;
  bool started_ = false, shared_ = false;
};

class Front {
 public:
  struct Gate {
    uint32_t a, b;
    uint32_t edge;  // the corner (triangle * 3 + slot) opposite this gate in its decoded triangle
    uint32_t apex;  // that triangle's vertex opposite the gate (at the slot)
    int32_t next_out, next_in;
    uint32_t open;
    uint32_t unused;  // 32 bytes: indexing by a shift
  };
  static constexpr uint32_t kNoEdge = 0xFFFFFFFFu;
  static constexpr int kMaxScan = 64;

  // Capacities for a mesh of this size. A triangle opens at most 3 gates, but a manifold mesh
  // opens about one per edge, and by Euler's formula edges = vertices + triangles - (2 per
  // component, less per hole or handle): 1.5 per triangle when closed, up to 3 for a triangle
  // soup. Gates start a little above that, never above the worst case (at 32 bytes each, the
  // worst case doubled the coder's largest array), and grow by half when a mesh needs more (a
  // copy that cost boundary-heavy CAD parts a few percent of their decode). Callers never code
  // more than `triangles` triangles (the neighbour tables are sized for them; vertices and gates
  // still grow if needed). Without `keep_edges` only the opposite vertices are recorded
  // (TakeOpposite is then empty). With `compact` (the encoder, which calls MakeRoom between
  // steps) the gates start at a quarter of a closed mesh's.
  void Reserve(size_t vertices, size_t triangles, bool keep_edges = true, bool compact = false) {
    GrowVertices(vertices < 16 ? 16 : vertices);
    const size_t edges = std::min(3 * triangles, vertices + triangles + triangles / 16);
    GrowGates(compact ? triangles / 4 + 64 : std::max(edges, 3 * triangles / 2) + 64);
    keep_edges_ = keep_edges;
    if (keep_edges_) opp_.assign(3 * triangles, kNoEdge);
    oppv_.assign(3 * triangles, kNoEdge);
  }
  uint32_t AddVertex() {
    if (num_vertices_ == vertex_capacity_) GrowVertices(2 * vertex_capacity_ + 16);
    vertices_[num_vertices_] = Vertex{-1, -1, 0};
    return num_vertices_++;
  }
  uint32_t num_vertices() const { return num_vertices_; }
  uint32_t degree(uint32_t v) const { return vertices_[v].deg; }  // triangles attached at v
  bool empty() const { return stack_top_ == 0; }
  // Pops the next gate; returns -1 if it was closed meanwhile.
  int32_t Pop() {
    const int32_t g = stack_[--stack_top_];
    return gates_[g].open ? g : -1;
  }
  const Gate& gate(int32_t g) const { return gates_[g]; }
  // Pop, also giving the gate's ends. The gate popped is most often the last one opened (the
  // traversal goes on from the triangle just attached); its ends are then taken from registers
  // instead of the gate just stored, which the pop would otherwise wait for (the decoder's loop is
  // bound by such chains from one gate to the next).
  O3DGC_INLINE int32_t PopWithEnds(uint32_t* a, uint32_t* b) {
    const int32_t g = stack_[--stack_top_];
    if (g == last_open_) {
      last_open_ = -1;
      *a = last_a_;
      *b = last_b_;
      return g;
    }
    if (!gates_[g].open) return -1;
    *a = gates_[g].a;
    *b = gates_[g].b;
    return g;
  }

  // The newest open gate leaving v / entering v, or -1 (closed gates at the head are dropped).
  int32_t HeadOut(uint32_t v) {
    int32_t g = vertices_[v].head_out;
    while (g >= 0 && !gates_[g].open) g = gates_[g].next_out;
    vertices_[v].head_out = g;
    return g;
  }
  int32_t HeadIn(uint32_t v) {
    int32_t g = vertices_[v].head_in;
    while (g >= 0 && !gates_[g].open) g = gates_[g].next_in;
    vertices_[v].head_in = g;
    return g;
  }

  // The context of gate a->b and the candidate third vertices: the end of the newest gate leaving
  // b ("right"), the start of the newest gate entering a ("left"), -1 if none.
  // `prev`: the previous gate outcome (0 before the first) for format 1.1's contexts, -1 for
  // format 1.0's. Why 1.1 adds them: on CAD tessellations (fans, strips of slivers) the outcomes
  // come in runs that the degree of a and the previous outcome predict.
  struct Candidates {
    int context;
    int64_t right, left;
    int32_t right_gate;  // the gate b->right, -1 if none
  };
  Candidates Look(uint32_t a, uint32_t b, int prev = -1) {
    const int32_t r = HeadOut(b), l = HeadIn(a);
    const uint32_t db = vertices_[b].deg, da = vertices_[a].deg;
    const uint32_t d = db < 7 ? db : 7;
    const int sides = (r >= 0) + 2 * (l >= 0);
    Candidates c;
    if (prev < 0) {
      c.context = int((sides * 2 + (da >= 5 ? 1 : 0)) * 8 + d);
    } else {
      c.context = int(((sides * 8 + (da < 7 ? da : 7)) * 8 + d) * kGateOutcomes) + prev;
    }
    c.right = r >= 0 ? int64_t(gates_[r].b) : -1;
    c.left = l >= 0 ? int64_t(gates_[l].a) : -1;
    c.right_gate = r;
    return c;
  }

  void Close(int32_t g) {
    gates_[g].open = 0;
    last_open_ = -1;
  }

  // Room for the 3 gates a step opens at most: when the array is full, the closed gates are
  // dropped (from the per-vertex lists and the stack, which skip them anyway) and the open ones
  // renumbered, and the array grows only if they still fill half of it. Gate ids are handles, so
  // the coding is the same; the array then holds about the front instead of every gate ever
  // opened (about 56 bytes per triangle of a large mesh). Only between steps: no gate id may be
  // held across it.
  void MakeRoom() {
    if (gate_capacity_ - num_gates_ >= 3) return;
    Compact();
    if (2 * num_gates_ + 3 > gate_capacity_) GrowGates(gate_capacity_ + gate_capacity_ / 2 + 16);
  }

  // Format 1.1 walks along the front: from v, `steps` times to the end of the newest open gate
  // leaving the vertex (`left` false) or to the start of the newest open gate entering it (`left`
  // true). Returns the vertex reached, or -1 if a vertex on the way has no such gate. One step
  // from b (right) or from a (left) reaches the gate's candidates.
  int64_t Walk(uint32_t v, bool left, uint32_t steps) {
    for (uint32_t i = 0; i < steps; ++i) {
      const int32_t g = left ? HeadIn(v) : HeadOut(v);
      if (g < 0) return -1;
      v = left ? gates_[g].a : gates_[g].b;
    }
    return v;
  }
  // The fewest steps (1..kMaxWalkSteps) of such a walk from v that reach `target`, 0 if none.
  uint32_t WalkSteps(uint32_t v, bool left, uint32_t target) {
    for (uint32_t i = 1; i <= kMaxWalkSteps; ++i) {
      const int32_t g = left ? HeadIn(v) : HeadOut(v);
      if (g < 0) return 0;
      v = left ? gates_[g].a : gates_[g].b;
      if (v == target) return i;
    }
    return 0;
  }

  // A new triangle edge u->v (edge = triangle * 3 + slot, the corner opposite the edge): closes
  // the open gate v->u if there is one (the two triangles become neighbours), else opens u->v.
  // Only the kMaxScan newest open gates leaving v are searched, so a vertex with very many open
  // gates (hostile streams, pathological meshes) cannot make coding quadratic; the encoder and the
  // decoder apply the same rule.
  // `apex`: the new triangle's vertex opposite the edge.
  // AddHalfEdge and Attach are forced inline into the coding loops: in WebAssembly a call there
  // makes the engine spill the loop's live values (V8 keeps no register across a call); inlined,
  // the wasm decoder takes 0.95x the time on igea, and native decoding is unchanged.
  O3DGC_INLINE void AddHalfEdge(uint32_t u, uint32_t v, uint32_t edge, uint32_t apex) {
    int32_t prev = -1;
    int scanned = 0;
    for (int32_t g = vertices_[v].head_out; g >= 0 && scanned < kMaxScan;) {
      Gate& x = gates_[g];
      const int32_t next = x.next_out;
      if (!x.open) {  // drop a closed gate from v's list on the way
        if (prev < 0) {
          vertices_[v].head_out = next;
        } else {
          gates_[prev].next_out = next;
        }
      } else if (x.b == u) {
        Link(edge, apex, x.edge, x.apex);
        x.open = 0;
        return;
      } else {
        prev = g;
        ++scanned;
      }
      g = next;
    }
    Open(u, v, edge, apex);
  }
  // Opens gate u->v (AddHalfEdge when v has no open gate to u).
  void Open(uint32_t u, uint32_t v, uint32_t edge, uint32_t apex) {
    if (num_gates_ == gate_capacity_) GrowGates(gate_capacity_ + gate_capacity_ / 2 + 16);
    const int32_t id = int32_t(num_gates_++);
    gates_[id] = Gate{u, v, edge, apex, vertices_[u].head_out, vertices_[v].head_in, 1, 0};
    vertices_[u].head_out = id;
    vertices_[v].head_in = id;
    stack_[stack_top_++] = id;
    last_open_ = id;
    last_a_ = u;
    last_b_ = v;
  }

  // Triangle `tri` = (x, y, z) starts a new part.
  void StartTriangle(uint32_t tri, uint32_t x, uint32_t y, uint32_t z) {
    last_open_ = -1;
    ++vertices_[x].deg;
    ++vertices_[y].deg;
    ++vertices_[z].deg;
    AddHalfEdge(x, y, tri * 3 + 2, z);
    AddHalfEdge(y, z, tri * 3 + 0, x);
    AddHalfEdge(z, x, tri * 3 + 1, y);
  }
  // What Attach knows beforehand of the gates b->c: nothing (kSearch), that c is new (kNoGate:
  // no gate touches c), or the one AddHalfEdge(c, b) would close (its id: the right candidate's
  // gate is the newest open gate leaving b, the first one the search meets). Knowing it spares the
  // search and changes nothing else.
  static constexpr int32_t kSearch = -2, kNoGate = -1;
  // Attaches triangle `tri` across the gate g = a->b; it is emitted as (b, a, c), or as (a, b, c)
  // when `flipped`.
  O3DGC_INLINE void Attach(int32_t g, uint32_t tri, uint32_t a, uint32_t b, uint32_t c,
                           bool flipped, int32_t gate_bc = kSearch) {
    last_open_ = -1;  // only a gate this attach opens is known open at the next pop
    Link(tri * 3 + 2, c, gates_[g].edge, gates_[g].apex);
    gates_[g].open = 0;
    ++vertices_[a].deg;
    ++vertices_[b].deg;
    ++vertices_[c].deg;
    const uint32_t edge = tri * 3 + (flipped ? 0 : 1);
    if (gate_bc == kNoGate) {
      // c is new: no gate leaves it, so a->c opens without a search of c's (empty) list.
      Open(a, c, tri * 3 + (flipped ? 1 : 0), b);
      Open(c, b, edge, a);
      return;
    }
    AddHalfEdge(a, c, tri * 3 + (flipped ? 1 : 0), b);
    if (gate_bc == kSearch) {
      AddHalfEdge(c, b, edge, a);
    } else {
      Link(edge, a, gates_[gate_bc].edge, gates_[gate_bc].apex);
      gates_[gate_bc].open = 0;
    }
  }
  // Neighbour relation found while coding: for triangle t and slot k (the edge opposite corner k),
  // opposite()[3t+k] is the neighbour's corner opposite that edge (triangle * 3 + slot), or
  // kNoEdge. Sized for `triangles`.
  std::vector<uint32_t> TakeOpposite(size_t triangles) {
    if (keep_edges_) opp_.resize(3 * triangles, kNoEdge);
    return std::move(opp_);
  }
  // The same as vertices: the neighbour's vertex opposite the shared edge, or kNoEdge.
  std::vector<uint32_t> TakeOppositeVertices(size_t triangles) {
    oppv_.resize(3 * triangles, kNoEdge);
    return std::move(oppv_);
  }

 private:
  // The edges opposite corners e1 and e2 (vertices v1 and v2) are neighbours. Both corners belong
  // to the `triangles` of Reserve.
  void Link(uint32_t e1, uint32_t v1, uint32_t e2, uint32_t v2) {
    oppv_[e1] = v2;
    oppv_[e2] = v1;
    if (keep_edges_) {
      opp_[e1] = e2;
      opp_[e2] = e1;
    }
  }
  template <typename T>
  static void Grow(std::unique_ptr<T[]>* a, size_t used, size_t capacity) {
    std::unique_ptr<T[]> b(new T[capacity]);  // left uninitialized: entries are written first
    std::copy(a->get(), a->get() + used, b.get());
    *a = std::move(b);
  }
  O3DGC_NOINLINE void GrowVertices(size_t capacity) {
    Grow(&vertices_, num_vertices_, capacity);
    vertex_capacity_ = capacity;
  }
  // See MakeRoom. The lists and the stack keep their order.
  O3DGC_NOINLINE void Compact() {
    auto relink = [this](int32_t head, int32_t Gate::*next) {
      int32_t first = -1, last = -1;
      for (int32_t g = head; g >= 0; g = gates_[g].*next) {
        if (!gates_[g].open) continue;
        if (last < 0) {
          first = g;
        } else {
          gates_[last].*next = g;
        }
        last = g;
      }
      if (last >= 0) gates_[last].*next = -1;
      return first;
    };
    for (uint32_t v = 0; v < num_vertices_; ++v) {
      vertices_[v].head_out = relink(vertices_[v].head_out, &Gate::next_out);
      vertices_[v].head_in = relink(vertices_[v].head_in, &Gate::next_in);
    }
    std::vector<int32_t> id(num_gates_, -1);
    size_t n = 0;
    for (size_t g = 0; g < num_gates_; ++g) {
      if (!gates_[g].open) continue;
      id[g] = int32_t(n);
      gates_[n++] = gates_[g];
    }
    auto renumber = [&id](int32_t g) { return g < 0 ? g : id[size_t(g)]; };
    for (size_t g = 0; g < n; ++g) {
      gates_[g].next_out = renumber(gates_[g].next_out);
      gates_[g].next_in = renumber(gates_[g].next_in);
    }
    for (uint32_t v = 0; v < num_vertices_; ++v) {
      vertices_[v].head_out = renumber(vertices_[v].head_out);
      vertices_[v].head_in = renumber(vertices_[v].head_in);
    }
    size_t top = 0;
    for (size_t k = 0; k < stack_top_; ++k) {
      if (id[size_t(stack_[k])] >= 0) stack_[top++] = id[size_t(stack_[k])];
    }
    stack_top_ = top;
    num_gates_ = n;
    last_open_ = renumber(last_open_);  // open, so it keeps a number
  }
  O3DGC_NOINLINE void GrowGates(size_t capacity) {
    Grow(&gates_, num_gates_, capacity);
    Grow(&stack_, stack_top_, capacity);  // never more entries than gates
    gate_capacity_ = capacity;
  }

  // Gates are never reused (but renumbered by Compact): at most one per AddHalfEdge, each on the
  // stack once.
  std::unique_ptr<Gate[]> gates_;
  std::unique_ptr<int32_t[]> stack_;
  size_t num_gates_ = 0, gate_capacity_ = 0, stack_top_ = 0;
  // The last gate opened since the last attach, close or new part (-1 if none), and its ends:
  // still open and on the top of the stack.
  int32_t last_open_ = -1;
  uint32_t last_a_ = 0, last_b_ = 0;
  struct Vertex {
    int32_t head_out, head_in;  // newest gate leaving / entering the vertex, -1 if none
    uint32_t deg;               // triangles at the vertex so far
  };
  std::unique_ptr<Vertex[]> vertices_;
  uint32_t num_vertices_ = 0;
  size_t vertex_capacity_ = 0;
  std::vector<uint32_t> opp_, oppv_;
  bool keep_edges_ = true;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_CONNECTIVITY_FRONT_H_
