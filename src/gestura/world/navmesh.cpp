#include "gestura/world/navmesh.hpp"

#include <DetourCommon.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshBuilder.h>
#include <DetourNavMeshQuery.h>
#include <Recast.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <queue>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

constexpr int kMaxPathPolys = 4096;
constexpr int kMaxStraight = 1024;
constexpr unsigned short kWalkFlag = 1;

// Recast objects freed however the build ends.
struct RecastBuild {
  rcContext ctx{false};
  rcHeightfield* solid = rcAllocHeightfield();
  rcCompactHeightfield* chf = rcAllocCompactHeightfield();
  rcContourSet* cset = rcAllocContourSet();
  rcPolyMesh* pmesh = rcAllocPolyMesh();
  rcPolyMeshDetail* dmesh = rcAllocPolyMeshDetail();
  ~RecastBuild() {
    rcFreeHeightField(solid);
    rcFreeCompactHeightfield(chf);
    rcFreeContourSet(cset);
    rcFreePolyMesh(pmesh);
    rcFreePolyMeshDetail(dmesh);
  }
};

}  // namespace

struct NavMesh::Impl {
  NavMeshSettings settings;
  dtNavMesh* mesh = nullptr;
  dtNavMeshQuery* query = nullptr;
  dtQueryFilter filter;
  int polygons = 0;
  std::vector<vec3> corners;          // inner corners of the floor outline, nudged onto the floor
  std::vector<dtPolyRef> corner_refs; // their polygons

  void find_corners();
  bool walk_straight(dtPolyRef ref, const vec3& from, const vec3& to) const {
    float t = 0.0f, normal[3];
    int n = 0;
    const dtStatus st = query->raycast(ref, &from.x, &to.x, &filter, &t, normal, nullptr, &n, 0);
    return dtStatusSucceed(st) && t > 1.0f;
  }

  ~Impl() {
    dtFreeNavMeshQuery(query);
    dtFreeNavMesh(mesh);
  }

  dtPolyRef nearest(const vec3& p, const vec3& extent, vec3* on_mesh) const {
    if (!query) return 0;
    dtPolyRef ref = 0;
    float out[3];
    if (dtStatusFailed(query->findNearestPoly(&p.x, &extent.x, &filter, &ref, out)) || ref == 0) return 0;
    // Detour accepts any polygon whose bounds meet the box; the point itself must lie within it.
    if (std::abs(out[0] - p.x) > extent.x || std::abs(out[1] - p.y) > extent.y || std::abs(out[2] - p.z) > extent.z) return 0;
    if (on_mesh) *on_mesh = vec3(out[0], out[1], out[2]);
    return ref;
  }
};

NavMesh::NavMesh() : impl_(std::make_unique<Impl>()) {}
NavMesh::~NavMesh() = default;
NavMesh::NavMesh(NavMesh&&) noexcept = default;
NavMesh& NavMesh::operator=(NavMesh&&) noexcept = default;

const NavMeshSettings& NavMesh::settings() const { return impl_->settings; }
bool NavMesh::empty() const { return impl_->polygons == 0; }
int NavMesh::polygon_count() const { return impl_->polygons; }

NavMesh NavMesh::build(const Environment& env, const NavMeshSettings& s) {
  if (!(s.agent_radius > 0.0f && s.agent_height > 0.0f && s.max_climb >= 0.0f && s.cell_size > 0.0f && s.cell_height > 0.0f))
    throw Error("navmesh: agent radius, height and cell sizes must be positive");
  NavMesh out;
  out.impl_->settings = s;
  if (env.triangle_count() == 0) return out;

  const Aabb bounds = env.bvh.bounds();
  rcConfig cfg;
  std::memset(&cfg, 0, sizeof cfg);
  cfg.cs = s.cell_size;
  cfg.ch = s.cell_height;
  cfg.walkableSlopeAngle = s.max_slope_degrees;
  cfg.walkableHeight = static_cast<int>(std::ceil(s.agent_height / cfg.ch));
  cfg.walkableClimb = static_cast<int>(std::floor(s.max_climb / cfg.ch));
  cfg.walkableRadius = static_cast<int>(std::ceil(s.agent_radius / cfg.cs + s.margin_cells));
  cfg.maxEdgeLen = static_cast<int>(12.0f / cfg.cs);
  cfg.maxSimplificationError = 1.1f;
  cfg.minRegionArea = 4 * 4;
  cfg.mergeRegionArea = 20 * 20;
  cfg.maxVertsPerPoly = DT_VERTS_PER_POLYGON;
  cfg.detailSampleDist = cfg.cs * 6.0f;
  cfg.detailSampleMaxError = cfg.ch * 1.0f;
  const vec3 pad(cfg.cs * 2.0f, 0.0f, cfg.cs * 2.0f);
  const vec3 bmin = bounds.min - pad, bmax = bounds.max + pad + vec3(0.0f, s.agent_height, 0.0f);
  std::memcpy(cfg.bmin, &bmin.x, sizeof cfg.bmin);
  std::memcpy(cfg.bmax, &bmax.x, sizeof cfg.bmax);
  rcCalcGridSize(cfg.bmin, cfg.bmax, cfg.cs, &cfg.width, &cfg.height);
  if (cfg.width > 16000 || cfg.height > 16000 || static_cast<long>(cfg.width) * cfg.height > 40'000'000L)
    throw Error("navmesh: the scene (" + std::to_string(static_cast<int>(bmax.x - bmin.x)) + " x " +
                std::to_string(static_cast<int>(bmax.z - bmin.z)) + " m) is too large for " + std::to_string(cfg.cs) +
                " m cells");

  RecastBuild b;
  const int nv = static_cast<int>(env.positions.size()), nt = static_cast<int>(env.triangle_count());
  std::vector<int> tris(env.indices.begin(), env.indices.end());
  std::vector<unsigned char> areas(static_cast<std::size_t>(nt), 0);
  const float* verts = &env.positions[0].x;
  if (!rcCreateHeightfield(&b.ctx, *b.solid, cfg.width, cfg.height, cfg.bmin, cfg.bmax, cfg.cs, cfg.ch))
    throw Error("navmesh: Recast could not allocate the height field");
  rcMarkWalkableTriangles(&b.ctx, cfg.walkableSlopeAngle, verts, nv, tris.data(), nt, areas.data());
  if (!rcRasterizeTriangles(&b.ctx, verts, nv, tris.data(), areas.data(), nt, *b.solid, cfg.walkableClimb))
    throw Error("navmesh: Recast could not rasterise the scene");
  rcFilterLowHangingWalkableObstacles(&b.ctx, cfg.walkableClimb, *b.solid);
  rcFilterLedgeSpans(&b.ctx, cfg.walkableHeight, cfg.walkableClimb, *b.solid);
  rcFilterWalkableLowHeightSpans(&b.ctx, cfg.walkableHeight, *b.solid);
  if (!rcBuildCompactHeightfield(&b.ctx, cfg.walkableHeight, cfg.walkableClimb, *b.solid, *b.chf))
    throw Error("navmesh: Recast could not build the compact height field");
  if (!rcErodeWalkableArea(&b.ctx, cfg.walkableRadius, *b.chf)) throw Error("navmesh: Recast could not erode by the radius");
  if (!rcBuildDistanceField(&b.ctx, *b.chf)) throw Error("navmesh: Recast could not build the distance field");
  if (!rcBuildRegions(&b.ctx, *b.chf, 0, cfg.minRegionArea, cfg.mergeRegionArea)) throw Error("navmesh: Recast could not build regions");
  if (!rcBuildContours(&b.ctx, *b.chf, cfg.maxSimplificationError, cfg.maxEdgeLen, *b.cset))
    throw Error("navmesh: Recast could not trace contours");
  if (!rcBuildPolyMesh(&b.ctx, *b.cset, cfg.maxVertsPerPoly, *b.pmesh)) throw Error("navmesh: Recast could not build polygons");
  if (b.pmesh->npolys == 0) return out;  // no walkable ground: an empty mesh
  if (!rcBuildPolyMeshDetail(&b.ctx, *b.pmesh, *b.chf, cfg.detailSampleDist, cfg.detailSampleMaxError, *b.dmesh))
    throw Error("navmesh: Recast could not build the detail mesh");
  if (b.pmesh->nverts >= 0xffff) throw Error("navmesh: more than 65535 vertices (use a coarser cell size)");

  std::vector<unsigned short> flags(static_cast<std::size_t>(b.pmesh->npolys), kWalkFlag);
  for (int i = 0; i < b.pmesh->npolys; ++i)
    if (b.pmesh->areas[i] == RC_WALKABLE_AREA) b.pmesh->areas[i] = 0;
  dtNavMeshCreateParams params;
  std::memset(&params, 0, sizeof params);
  params.verts = b.pmesh->verts;
  params.vertCount = b.pmesh->nverts;
  params.polys = b.pmesh->polys;
  params.polyAreas = b.pmesh->areas;
  params.polyFlags = flags.data();
  params.polyCount = b.pmesh->npolys;
  params.nvp = b.pmesh->nvp;
  params.detailMeshes = b.dmesh->meshes;
  params.detailVerts = b.dmesh->verts;
  params.detailVertsCount = b.dmesh->nverts;
  params.detailTris = b.dmesh->tris;
  params.detailTriCount = b.dmesh->ntris;
  params.walkableHeight = s.agent_height;
  params.walkableRadius = s.agent_radius;
  params.walkableClimb = s.max_climb;
  std::memcpy(params.bmin, b.pmesh->bmin, sizeof params.bmin);
  std::memcpy(params.bmax, b.pmesh->bmax, sizeof params.bmax);
  params.cs = cfg.cs;
  params.ch = cfg.ch;
  params.buildBvTree = true;
  unsigned char* data = nullptr;
  int size = 0;
  if (!dtCreateNavMeshData(&params, &data, &size)) throw Error("navmesh: Detour could not pack the mesh");
  Impl& impl = *out.impl_;
  impl.mesh = dtAllocNavMesh();
  if (!impl.mesh || dtStatusFailed(impl.mesh->init(data, size, DT_TILE_FREE_DATA))) {
    dtFree(data);
    throw Error("navmesh: Detour could not load the mesh");
  }
  impl.query = dtAllocNavMeshQuery();
  if (!impl.query || dtStatusFailed(impl.query->init(impl.mesh, 8192))) throw Error("navmesh: Detour could not set up queries");
  impl.filter.setIncludeFlags(kWalkFlag);
  impl.filter.setExcludeFlags(0);
  impl.polygons = b.pmesh->npolys;
  impl.find_corners();
  return out;
}

void NavMesh::Impl::find_corners() {
  const dtMeshTile* tile = static_cast<const dtNavMesh*>(mesh)->getTile(0);
  if (!tile || !tile->header) return;
  const int nverts = tile->header->vertCount;
  auto vert = [&](int i) { return vec3(tile->verts[3 * i], tile->verts[3 * i + 1], tile->verts[3 * i + 2]); };
  // Directed outline edges in each polygon's winding; the winding's sense from the polygons' areas.
  std::vector<int> next(static_cast<std::size_t>(nverts), -1), prev(static_cast<std::size_t>(nverts), -1);
  float winding = 0.0f;
  for (int p = 0; p < tile->header->polyCount; ++p) {
    const dtPoly& poly = tile->polys[p];
    for (int k = 0; k < poly.vertCount; ++k) {
      const vec3 a = vert(poly.verts[k]), c = vert(poly.verts[(k + 1) % poly.vertCount]);
      winding += a.x * c.z - c.x * a.z;
      if (poly.neis[k] != 0) continue;
      next[poly.verts[k]] = poly.verts[(k + 1) % poly.vertCount];
      prev[poly.verts[(k + 1) % poly.vertCount]] = poly.verts[k];
    }
  }
  const float sense = winding >= 0.0f ? 1.0f : -1.0f;  // +1: the floor lies left of its edges (x–z)
  for (int v = 0; v < nverts; ++v) {
    if (next[v] < 0 || prev[v] < 0) continue;
    const vec3 a = vert(prev[v]), o = vert(v), c = vert(next[v]);
    const vec2 din(o.x - a.x, o.z - a.z), dout(c.x - o.x, c.z - o.z);
    if (glm::length(din) < 1e-5f || glm::length(dout) < 1e-5f) continue;
    const float turn = din.x * dout.y - din.y * dout.x;
    if (turn * sense > -1e-6f * glm::length(din) * glm::length(dout)) continue;  // not a reflex corner of the floor
    const vec2 nin = sense * vec2(-din.y, din.x) / glm::length(din), nout = sense * vec2(-dout.y, dout.x) / glm::length(dout);
    vec2 inward = nin + nout;
    if (glm::length(inward) < 1e-5f) continue;
    inward = glm::normalize(inward) * 0.02f;
    const vec3 nudged(o.x + inward.x, o.y, o.z + inward.y);
    vec3 on;
    const dtPolyRef ref = nearest(nudged, vec3(0.05f, 0.5f, 0.05f), &on);
    if (!ref) continue;
    corners.push_back(on);
    corner_refs.push_back(ref);
  }
}

std::size_t NavMesh::corner_count() const { return impl_->corners.size(); }

std::optional<std::vector<vec3>> NavMesh::visibility_path(const vec3& start, const vec3& goal, float bound) const {
  const Impl& m = *impl_;
  if (!m.query) return std::nullopt;
  vec3 s, g;
  const dtPolyRef sref = m.nearest(start, vec3(0.05f, 0.5f, 0.05f), &s);
  const dtPolyRef gref = m.nearest(goal, vec3(0.05f, 0.5f, 0.05f), &g);
  if (!sref || !gref) return std::nullopt;
  // Nodes: 0 start, 1 goal, then the corners.
  std::vector<vec3> nodes{s, g};
  std::vector<dtPolyRef> refs{sref, gref};
  nodes.insert(nodes.end(), m.corners.begin(), m.corners.end());
  refs.insert(refs.end(), m.corner_refs.begin(), m.corner_refs.end());
  const std::size_t n = nodes.size();
  auto plan_distance = [&](std::size_t a, std::size_t b) {
    return std::sqrt((nodes[a].x - nodes[b].x) * (nodes[a].x - nodes[b].x) + (nodes[a].z - nodes[b].z) * (nodes[a].z - nodes[b].z));
  };
  const float limit = bound * (1.0f + 1e-4f) + 1e-4f;
  std::vector<float> cost(n, std::numeric_limits<float>::infinity());
  std::vector<std::size_t> parent(n, n);
  std::vector<char> closed(n, 0);
  using Item = std::pair<float, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  cost[0] = 0.0f;
  open.push({plan_distance(0, 1), 0});
  while (!open.empty()) {
    const auto [f, u] = open.top();
    open.pop();
    if (closed[u]) continue;
    closed[u] = 1;
    if (u == 1) break;
    for (std::size_t v = 1; v < n; ++v) {
      if (closed[v]) continue;
      const float c = cost[u] + plan_distance(u, v);
      if (c >= cost[v] || c + plan_distance(v, 1) > limit) continue;
      if (!m.walk_straight(refs[u], nodes[u], nodes[v])) continue;
      cost[v] = c;
      parent[v] = u;
      open.push({c + plan_distance(v, 1), v});
    }
  }
  if (!closed[1]) return std::nullopt;
  std::vector<vec3> path;
  for (std::size_t v = 1; v != n; v = parent[v]) path.push_back(nodes[v]);
  std::reverse(path.begin(), path.end());
  return path;
}

std::optional<vec3> NavMesh::nearest_point(const vec3& p, const vec3& search) const {
  vec3 on;
  if (!impl_->nearest(p, search, &on)) return std::nullopt;
  return on;
}

NavPath NavMesh::find_path(const vec3& start, const vec3& goal, const vec3& snap) const {
  NavPath out;
  vec3 s, g;
  const dtPolyRef sref = impl_->nearest(start, snap, &s);
  if (!sref) return out.status = NavQueryStatus::StartOffMesh, out;
  const dtPolyRef gref = impl_->nearest(goal, snap, &g);
  if (!gref) return out.status = NavQueryStatus::GoalOffMesh, out;
  std::vector<dtPolyRef> corridor(kMaxPathPolys);
  int count = 0;
  // Any-angle search (Detour shortcuts each node to its grandparent when a ray walks straight there):
  // path costs then measure straight lines, not hops between polygon edge midpoints, so the search
  // picks the way round obstacles that is really shortest.
  dtStatus st = impl_->query->initSlicedFindPath(sref, gref, &s.x, &g.x, &impl_->filter, DT_FINDPATH_ANY_ANGLE);
  while (dtStatusInProgress(st)) st = impl_->query->updateSlicedFindPath(1 << 20, nullptr);
  if (dtStatusSucceed(st)) st = impl_->query->finalizeSlicedFindPath(corridor.data(), &count, kMaxPathPolys);
  if (dtStatusFailed(st) || count == 0) return out.status = NavQueryStatus::Disconnected, out;
  vec3 end = g;
  if (corridor[static_cast<std::size_t>(count - 1)] != gref) {
    // A partial corridor: the goal's polygon is not reachable. Keep the nearest reachable point.
    out.status = NavQueryStatus::Disconnected;
    impl_->query->closestPointOnPoly(corridor[static_cast<std::size_t>(count - 1)], &g.x, &end.x, nullptr);
  }
  std::vector<float> straight(3 * kMaxStraight);
  int n = 0;
  impl_->query->findStraightPath(&s.x, &end.x, corridor.data(), count, straight.data(), nullptr, nullptr, &n, kMaxStraight);
  for (int i = 0; i < n; ++i) out.points.push_back(vec3(straight[3 * i], straight[3 * i + 1], straight[3 * i + 2]));
  if (out.points.empty()) out.points = {s, end};
  return out;
}

vec3 NavMesh::move_along_surface(const vec3& from, const vec3& to) const {
  vec3 start;
  const dtPolyRef ref = impl_->nearest(from, vec3(0.5f, 1.0f, 0.5f), &start);
  if (!ref) return from;
  float result[3];
  dtPolyRef visited[16];
  int nvisited = 0;
  impl_->query->moveAlongSurface(ref, &start.x, &to.x, &impl_->filter, result, visited, &nvisited, 16);
  vec3 r(result[0], result[1], result[2]);
  if (nvisited > 0) {
    float h = r.y;
    if (dtStatusSucceed(impl_->query->getPolyHeight(visited[nvisited - 1], result, &h))) r.y = h;
  }
  return r;
}

bool NavMesh::straight_walkable(const vec3& a, const vec3& b) const {
  vec3 start;
  const dtPolyRef ref = impl_->nearest(a, vec3(0.2f, 1.0f, 0.2f), &start);
  if (!ref) return false;
  float t = 0.0f, normal[3];
  int n = 0;
  const dtStatus st = impl_->query->raycast(ref, &start.x, &b.x, &impl_->filter, &t, normal, nullptr, &n, 0);
  return dtStatusSucceed(st) && t > 1.0f;  // FLT_MAX: no wall hit
}

std::vector<vec3> NavMesh::boundary_edges() const {
  std::vector<vec3> edges;
  const dtNavMesh* mesh = impl_->mesh;
  if (!mesh) return edges;
  for (int ti = 0; ti < mesh->getMaxTiles(); ++ti) {
    const dtMeshTile* tile = mesh->getTile(ti);
    if (!tile || !tile->header) continue;
    for (int p = 0; p < tile->header->polyCount; ++p) {
      const dtPoly& poly = tile->polys[p];
      for (int k = 0; k < poly.vertCount; ++k) {
        if (poly.neis[k] != 0) continue;  // shared with a neighbour: not on the outline
        const float* a = &tile->verts[3 * poly.verts[k]];
        const float* c = &tile->verts[3 * poly.verts[(k + 1) % poly.vertCount]];
        edges.push_back(vec3(a[0], a[1], a[2]));
        edges.push_back(vec3(c[0], c[1], c[2]));
      }
    }
  }
  return edges;
}

}  // namespace gestura
