// Embree counterpart of the Java project's "real-mesh" benchmark scene (benchmark.Benchmark, obj:PATH),
// and optionally scene S (three spheres on the floor).
//
// Scene (as in Benchmark.java / RayTracerBasic.java / LightSquare.java):
//  - camera at (0,0,1000) looking -z, up +y, right +x; view plane 150 x 150 at distance 1000; 800 x 800
//    pixels, one primary ray per pixel through the pixel centre;
//  - floor: the plane y = -50 (here a quad of two triangles, x,z in [-1e6, 1e6], which covers every
//    primary ray below the horizon: the farthest floor hit is at z ~ -5.3e5, |x| < 4e4);
//  - mesh: the OBJ's triangles (polygons split as a fan around the first vertex, degenerate triangles
//    skipped as Polygon.edgesOf does), scaled so the largest extent of the bounding box is 75,
//    centred in x and z, standing on the floor (min y -> -50);
//  - light: a square of edge 40 centred at (-70,100,40), U = (1,0,0), V = (0,0,1) (scene S: edge 20 at
//    (0,100,0));
//  - a hit point is lit (traces shadow rays) iff alignZero(n.l) * alignZero(n.v) > 0, n the face normal,
//    v the primary ray direction, l the unit vector light centre -> point;
//  - 82 shadow rays per lit point: one to the centre of the square plus one to a jittered point in each
//    of the 9 x 9 cells; each starts at p + DELTA*n/|n| (DELTA = 0.1) on the side its direction leaves to
//    (not moved if the direction is orthogonal to n), and is as long as the distance from p to its target.
//
// Modes: "packet": shadow rays in rtcOccluded16 packets (82 = 5 x 16 + 2: six packets a point, the last
// with 2 valid lanes), coherent context; "single": rtcOccluded1 one at a time. Primary rays: rtcIntersect1.
//
// With --rays FILE it renders nothing: it traces the shadow rays of a file, bundle by bundle, in the mode's
// way (a bundle's rays in packets of 16 in its order, or one at a time), and reports Embree's thread time per
// ray on exactly those rays and how often its answer differs from the one in the file. The file holds
// bundles, each an int32 ray count and per ray 8 doubles (origin, unit direction, length, the Java
// renderer's transmittance), little-endian: the rays the Java renderer traced (tools/embree/README.md).
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

static const double DELTA = 0.1;
static const double EPS = 1e-10;
static inline double alignZero(double x) { return std::fabs(x) < EPS ? 0.0 : x; }

struct V3 {
    double x, y, z;
};
static inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
static inline V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
static inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static inline double len(V3 a) { return std::sqrt(dot(a, a)); }
static inline V3 normalize(V3 a) { return a * (1.0 / len(a)); }

// ---------------------------------------------------------------- scene
static const int SIZE = 800;
static const double VP = 150, VP_DIST = 1000;
static const V3 CAM = {0, 0, 1000};
static const double FLOOR_Y = -50;
static const double FLOOR_HALF = 1e6;
static const int SQRT_BEAM = 9;
static const int SHADOW_RAYS = 1 + SQRT_BEAM * SQRT_BEAM; // 82

struct Scene {
    std::vector<V3> verts;             // mesh vertices, placed (double)
    std::vector<unsigned> tris;        // 3 per triangle
    std::vector<V3> faceNormals;       // unit (p2-p1)x(p3-p2), one per triangle
    std::vector<V3> sphereC;           // scene S
    std::vector<double> sphereR;
    V3 light;
    double edge;
    V3 u = {1, 0, 0}, v = {0, 0, 1};
    unsigned floorGeom = 0, meshGeom = RTC_INVALID_GEOMETRY_ID, sphereGeom = RTC_INVALID_GEOMETRY_ID;
};

// Polygon.edgesOf: degenerate if two consecutive vertices are within 1e-9 of the longest edge, or the
// sine between consecutive edges is zero (|sin| < 1e-10).
static bool degenerate(V3 a, V3 b, V3 c) {
    V3 p[3] = {a, b, c};
    double longest = 0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, len(p[(i + 1) % 3] - p[i]));
    V3 e[3];
    for (int i = 0; i < 3; ++i) {
        if (len(p[(i + 1) % 3] - p[i]) <= 1e-9 * longest) return true;
        e[i] = p[(i + 1) % 3] - p[i];
    }
    for (int i = 0; i < 3; ++i) {
        double s = len(cross(e[i], e[(i + 1) % 3])) / (len(e[i]) * len(e[(i + 1) % 3]));
        if (std::fabs(s) < EPS) return true;
    }
    return false;
}

static int parseIndex(const std::string &tok, int count) {
    int i = std::atoi(tok.c_str()); // stops at '/'
    return i > 0 ? i - 1 : count + i;
}

static void loadObj(const char *path, Scene &s) {
    std::ifstream in(path);
    if (!in) { std::fprintf(stderr, "cannot read %s\n", path); std::exit(1); }
    std::vector<V3> raw;
    std::vector<std::vector<int>> faces;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string kw;
        if (!(ls >> kw)) continue;
        if (kw == "v") {
            float x, y, z; // the Java library reads coordinates as floats
            ls >> x >> y >> z;
            raw.push_back({x, y, z});
        } else if (kw == "f") {
            std::vector<int> f;
            std::string tok;
            while (ls >> tok) f.push_back(parseIndex(tok, (int)raw.size()));
            faces.push_back(f);
        }
    }
    V3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (V3 p : raw) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    double extent = std::max(hi.x - lo.x, std::max(hi.y - lo.y, hi.z - lo.z));
    double scale = 75 / extent;
    V3 pos = {-scale * (lo.x + hi.x) / 2, FLOOR_Y - scale * lo.y, -scale * (lo.z + hi.z) / 2};
    for (V3 p : raw) s.verts.push_back({pos.x + scale * p.x, pos.y + scale * p.y, pos.z + scale * p.z});
    int skipped = 0;
    for (auto &f : faces)
        for (size_t k = 1; k + 1 < f.size(); ++k) {
            V3 a = s.verts[f[0]], b = s.verts[f[k]], c = s.verts[f[k + 1]];
            if (degenerate(a, b, c)) { ++skipped; continue; }
            s.tris.push_back(f[0]); s.tris.push_back(f[k]); s.tris.push_back(f[k + 1]);
            s.faceNormals.push_back(normalize(cross(b - a, c - b)));
        }
    std::printf("%s: %zu vertices, %zu triangles (%d degenerate skipped), scaled by %.4g\n", path,
                s.verts.size(), s.tris.size() / 3, skipped, scale);
}

// ---------------------------------------------------------------- spheres (scene S) as user geometry
static void sphereBounds(const RTCBoundsFunctionArguments *args) {
    const Scene *s = (const Scene *)args->geometryUserPtr;
    V3 c = s->sphereC[args->primID];
    float r = (float)s->sphereR[args->primID];
    RTCBounds *b = args->bounds_o;
    b->lower_x = c.x - r; b->lower_y = c.y - r; b->lower_z = c.z - r;
    b->upper_x = c.x + r; b->upper_y = c.y + r; b->upper_z = c.z + r;
}

// returns the nearest t in (tnear, tfar), or -1
static inline double sphereHit(V3 c, double r, V3 o, V3 d, double tnear, double tfar) {
    V3 oc = o - c;
    double b = dot(oc, d), cc = dot(oc, oc) - r * r;
    double disc = b * b - cc;
    if (disc < 0) return -1;
    double sq = std::sqrt(disc);
    double t0 = -b - sq, t1 = -b + sq;
    if (t0 > tnear && t0 < tfar) return t0;
    if (t1 > tnear && t1 < tfar) return t1;
    return -1;
}

// The distance along lane i of a ray stream to sphere primID of the scene (in the ray's own units,
// its direction not unit), or < 0 for no hit within [tnear, tfar].
static double laneSphereHit(const Scene *s, unsigned primID, RTCRayN *ray, unsigned N, unsigned i) {
    V3 o = {RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i)};
    V3 d = {RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i)};
    double dl = len(d);
    d = d * (1 / dl);
    double t = sphereHit(s->sphereC[primID], s->sphereR[primID], o, d, RTCRayN_tnear(ray, N, i) * dl,
                         RTCRayN_tfar(ray, N, i) * dl);
    return t < 0 ? t : t / dl;
}

static void sphereIntersect(const RTCIntersectFunctionNArguments *args) {
    const Scene *s = (const Scene *)args->geometryUserPtr;
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        RTCRayHitN *rh = args->rayhit;
        RTCRayN *ray = RTCRayHitN_RayN(rh, args->N);
        RTCHitN *hit = RTCRayHitN_HitN(rh, args->N);
        double t = laneSphereHit(s, args->primID, ray, args->N, i);
        if (t < 0) continue;
        RTCRayN_tfar(ray, args->N, i) = (float)t;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_u(hit, args->N, i) = 0; RTCHitN_v(hit, args->N, i) = 0;
        RTCHitN_Ng_x(hit, args->N, i) = 0; RTCHitN_Ng_y(hit, args->N, i) = 1; RTCHitN_Ng_z(hit, args->N, i) = 0;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
    }
}

static void sphereOccluded(const RTCOccludedFunctionNArguments *args) {
    const Scene *s = (const Scene *)args->geometryUserPtr;
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] && laneSphereHit(s, args->primID, args->ray, args->N, i) >= 0)
            RTCRayN_tfar(args->ray, args->N, i) = -INFINITY;
}

// ---------------------------------------------------------------- rendering
// A shadow ray from o along d, as long as tfar, in one ray or in lane k of a packet.
static void setRay(RTCRay &r, V3 o, V3 d, double tfar) {
    r.org_x = (float)o.x; r.org_y = (float)o.y; r.org_z = (float)o.z;
    r.dir_x = (float)d.x; r.dir_y = (float)d.y; r.dir_z = (float)d.z;
    r.tnear = 0; r.tfar = (float)tfar; r.time = 0; r.mask = 0xFFFFFFFF; r.id = 0; r.flags = 0;
}

static void setLane(RTCRay16 &r, int k, V3 o, V3 d, double tfar) {
    r.org_x[k] = (float)o.x; r.org_y[k] = (float)o.y; r.org_z[k] = (float)o.z;
    r.dir_x[k] = (float)d.x; r.dir_y[k] = (float)d.y; r.dir_z[k] = (float)d.z;
    r.tnear[k] = 0; r.tfar[k] = (float)tfar; r.time[k] = 0; r.mask[k] = 0xFFFFFFFF; r.id[k] = 0; r.flags[k] = 0;
}

struct Rng { // splitmix64
    uint64_t s;
    inline double next() {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return (z >> 11) * 0x1.0p-53;
    }
};

struct Result {
    long long shadowRays = 0, litPoints = 0, primaryHits = 0;
};

struct Renderer {
    Scene &sc;
    RTCScene rs;
    bool packets;
    std::vector<float> factor;   // shadow factor per pixel, -1 for background
    std::vector<uint8_t> grey;   // 255 * 0.8 * |n.l| * factor, as the Java picture (no ambient, kS 0)

    // shadow rays of one lit point p with normal n (unit); returns the unblocked count
    int shadow(V3 p, V3 n, V3 l, Rng &rng, RTCIntersectContext *ctx) {
        V3 nd = n * DELTA; // n is unit: DELTA / |n| = DELTA
        // origins, directions, lengths
        alignas(64) RTCRay16 r16;
        alignas(64) int valid[16];
        int unblocked = 0;
        int lane = 0;
        auto flush = [&](int lanes) {
            for (int k = 0; k < 16; ++k) valid[k] = k < lanes ? -1 : 0;
            rtcOccluded16(valid, rs, ctx, &r16);
            for (int k = 0; k < lanes; ++k) unblocked += r16.tfar[k] >= 0;
        };
        auto emit = [&](V3 o, V3 d, double dist) {
            if (packets) {
                setLane(r16, lane, o, d, dist);
                if (++lane == 16) { flush(16); lane = 0; }
            } else {
                RTCRay r;
                setRay(r, o, d, dist);
                rtcOccluded1(rs, ctx, &r);
                unblocked += r.tfar >= 0;
            }
        };
        // the centre ray: along -l, as long as the distance to the light's centre
        {
            V3 d = l * -1.0;
            double side = alignZero(dot(n, d));
            V3 o = side == 0 ? p : p + nd * (side > 0 ? 1.0 : -1.0);
            emit(o, d, len(sc.light - p));
        }
        const double e = sc.edge, cell = 1.0 / SQRT_BEAM;
        for (int i = 0; i < SQRT_BEAM; ++i)
            for (int j = 0; j < SQRT_BEAM; ++j) {
                double su = (i + rng.next()) * cell, sv = (j + rng.next()) * cell;
                double du = (0.5 - su) * e, dv = (0.5 - sv) * e;
                V3 d = sc.light + sc.u * du + sc.v * dv - p;
                double dist = len(d);
                d = d * (1 / dist);
                double side = alignZero(dot(nd, d)); // as LightSquare.traceSamples: n scaled to DELTA
                V3 o = side == 0 ? p : p + nd * (side > 0 ? 1.0 : -1.0);
                emit(o, d, dist);
            }
        if (packets && lane > 0) flush(lane);
        return unblocked;
    }

    void renderRows(std::atomic<int> &nextRow, Result &res, uint64_t seed) {
        RTCIntersectContext ctx1, ctxS;
        rtcInitIntersectContext(&ctx1);
        rtcInitIntersectContext(&ctxS);
        if (packets) ctxS.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        Rng rng{seed};
        const double pix = VP / SIZE;
        for (;;) {
            int i = nextRow.fetch_add(1);
            if (i >= SIZE) break;
            for (int j = 0; j < SIZE; ++j) {
                // Camera.constructRayThroughPixel: right = (j+0.5-N/2)*w/N, up = -(i+0.5-N/2)*h/N
                double xr = (j + 0.5 - SIZE / 2.0) * pix, yu = -(i + 0.5 - SIZE / 2.0) * pix;
                V3 dir = normalize({xr, yu, -VP_DIST});
                RTCRayHit rh;
                rh.ray.org_x = (float)CAM.x; rh.ray.org_y = (float)CAM.y; rh.ray.org_z = (float)CAM.z;
                rh.ray.dir_x = (float)dir.x; rh.ray.dir_y = (float)dir.y; rh.ray.dir_z = (float)dir.z;
                rh.ray.tnear = 0; rh.ray.tfar = INFINITY; rh.ray.time = 0; rh.ray.mask = 0xFFFFFFFF;
                rh.ray.id = 0; rh.ray.flags = 0;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID; rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(rs, &ctx1, &rh);
                size_t px = (size_t)i * SIZE + j;
                if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) { factor[px] = -1; grey[px] = 0; continue; }
                ++res.primaryHits;
                double t = rh.ray.tfar;
                V3 p = CAM + dir * t, n;
                if (rh.hit.geomID == sc.floorGeom) {
                    p.y = FLOOR_Y; // the plane's point, exactly on it
                    n = {0, 1, 0};
                } else if (rh.hit.geomID == sc.meshGeom) {
                    n = sc.faceNormals[rh.hit.primID];
                } else { // sphere: recompute t in double
                    V3 c = sc.sphereC[rh.hit.primID];
                    double td = sphereHit(c, sc.sphereR[rh.hit.primID], CAM, dir, 0, INFINITY);
                    p = CAM + dir * td;
                    n = normalize(p - c);
                }
                double nv = alignZero(dot(n, dir));
                V3 l = normalize(p - sc.light);
                double nl = alignZero(dot(n, l));
                if (nv == 0 || !(nl * nv > 0)) { factor[px] = 0; grey[px] = 0; continue; }
                ++res.litPoints;
                int ok = shadow(p, n, l, rng, &ctxS);
                res.shadowRays += SHADOW_RAYS;
                double f = (double)ok / SHADOW_RAYS;
                factor[px] = (float)f;
                double g = 255 * 0.8 * std::fabs(nl) * f;
                grey[px] = (uint8_t)std::lround(std::min(255.0, g));
            }
        }
    }

    Result frame(int threads, uint64_t frameNo) {
        std::atomic<int> nextRow{0};
        std::vector<Result> res(threads);
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t)
            pool.emplace_back([&, t] { renderRows(nextRow, res[t], 0x1234567ull * (frameNo * 16 + t + 1)); });
        for (auto &th : pool) th.join();
        Result total;
        for (auto &r : res) {
            total.shadowRays += r.shadowRays; total.litPoints += r.litPoints; total.primaryHits += r.primaryHits;
        }
        return total;
    }
};

static void writePgm(const char *path, const std::vector<uint8_t> &g) {
    FILE *f = std::fopen(path, "wb");
    std::fprintf(f, "P5\n%d %d\n255\n", SIZE, SIZE);
    std::fwrite(g.data(), 1, g.size(), f);
    std::fclose(f);
}

static double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

// The shadow rays of a file: bundle b holds rays [start[b], start[b + 1]).
struct RayFile {
    std::vector<double> rays; // 8 a ray: origin, direction, length, the renderer's transmittance
    std::vector<size_t> start{0};

    size_t count() const { return start.back(); }

    static RayFile read(const char *path) {
        RayFile f;
        FILE *in = std::fopen(path, "rb");
        if (!in) { std::fprintf(stderr, "cannot read %s\n", path); std::exit(1); }
        int32_t n;
        while (std::fread(&n, sizeof n, 1, in) == 1) {
            size_t at = f.rays.size();
            if (n > 0) f.rays.resize(at + 8 * (size_t)n); // a count read from a damaged file may be negative
            if (n <= 0 || std::fread(&f.rays[at], sizeof(double), 8 * (size_t)n, in) != 8 * (size_t)n) {
                std::fprintf(stderr, "%s: a bundle of %d rays is cut short or has no rays\n", path, n);
                std::exit(1);
            }
            f.start.push_back(f.start.back() + n);
        }
        std::fclose(in);
        return f;
    }
};

// Traces the file's bundles [from, to); returns how many answers differ from the file's (blocked or not).
static long long traceBundles(const RayFile &f, RTCScene rs, bool packets, size_t from, size_t to) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    if (packets) ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    long long differ = 0;
    alignas(64) RTCRay16 r16;
    alignas(64) int valid[16];
    auto origin = [&](size_t r) { return V3{f.rays[8 * r], f.rays[8 * r + 1], f.rays[8 * r + 2]}; };
    auto direction = [&](size_t r) { return V3{f.rays[8 * r + 3], f.rays[8 * r + 4], f.rays[8 * r + 5]}; };
    auto blocked = [&](size_t r) { return f.rays[8 * r + 7] == 0; };
    for (size_t b = from; b < to; ++b)
        for (size_t first = f.start[b]; first < f.start[b + 1]; first += packets ? 16 : 1) {
            if (!packets) {
                RTCRay r;
                setRay(r, origin(first), direction(first), f.rays[8 * first + 6]);
                rtcOccluded1(rs, &ctx, &r);
                differ += (r.tfar < 0) != blocked(first);
                continue;
            }
            int lanes = (int)std::min<size_t>(16, f.start[b + 1] - first);
            for (int k = 0; k < 16; ++k) { // idle lanes repeat the last ray, so that they hold a valid one
                size_t r = first + std::min(k, lanes - 1);
                valid[k] = k < lanes ? -1 : 0;
                setLane(r16, k, origin(r), direction(r), f.rays[8 * r + 6]);
            }
            rtcOccluded16(valid, rs, &ctx, &r16);
            for (int k = 0; k < lanes; ++k)
                differ += (r16.tfar[k] < 0) != blocked(first + k);
        }
    return differ;
}

// Traces every bundle of a file once on some threads, each taking runs of 64 bundles; returns the differing answers.
static long long tracePass(const RayFile &f, RTCScene rs, bool packets, int threads) {
    std::atomic<size_t> next{0};
    std::atomic<long long> differ{0};
    std::vector<std::thread> pool;
    size_t bundles = f.start.size() - 1;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (size_t from; (from = next.fetch_add(64)) < bundles;)
                differ += traceBundles(f, rs, packets, from, std::min(bundles, from + 64));
        });
    for (auto &th : pool) th.join();
    return differ;
}

// Times the passes over a file's rays and prints a RAYS line.
static void timeRayFile(const char *path, const std::string &mode, RTCScene rs, int threads, int warmup, int frames) {
    RayFile f = RayFile::read(path);
    std::vector<double> secs;
    long long differ = 0;
    for (int p = 0; p < warmup + frames; ++p) {
        auto t0 = std::chrono::steady_clock::now();
        differ = tracePass(f, rs, mode == "packet", threads);
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (p >= warmup) secs.push_back(s);
    }
    double med = median(secs);
    std::printf("RAYS file=%s mode=%s bundles=%zu rays=%zu median_s=%.4f ns_per_ray_thread_time=%.1f"
                " answers_differing=%lld\n", path, mode.c_str(), f.start.size() - 1, f.count(), med,
                threads * med * 1e9 / f.count(), differ);
}

int main(int argc, char **argv) {
    std::string sceneName, mode = "packet", image, quality = "medium", spheres = "point", rayFile;
    int threads = 2, warmup = 5, frames = 5;
    for (int a = 1; a + 1 < argc; a += 2) {
        std::string k = argv[a], v = argv[a + 1];
        if (k == "--scene") sceneName = v;
        else if (k == "--mode") mode = v;
        else if (k == "--threads") threads = std::atoi(v.c_str());
        else if (k == "--warmup") warmup = std::atoi(v.c_str());
        else if (k == "--frames") frames = std::atoi(v.c_str());
        else if (k == "--image") image = v;
        else if (k == "--quality") quality = v;
        else if (k == "--spheres") spheres = v;
        else if (k == "--rays") rayFile = v;
        else { std::fprintf(stderr, "unknown option %s\n", k.c_str()); return 2; }
    }
    if (sceneName.empty() || (mode != "packet" && mode != "single")) {
        std::fprintf(stderr, "usage: embree_bench --scene obj:PATH|S [--mode packet|single] [--threads 2]"
                             " [--warmup 5] [--frames 5] [--image out.pgm] [--quality low|medium|high]"
                             " [--spheres point|user] [--rays FILE]\n");
        return 2;
    }
    Scene sc;
    if (sceneName == "S") {
        sc.sphereC = {{-40, -20, 0}, {30, -30, 20}, {5, -35, -50}};
        sc.sphereR = {30, 20, 15};
        sc.light = {0, 100, 0};
        sc.edge = 20;
    } else if (sceneName.rfind("obj:", 0) == 0) {
        loadObj(sceneName.c_str() + 4, sc);
        sc.light = {-70, 100, 40};
        sc.edge = 40;
    } else { std::fprintf(stderr, "scene must be obj:PATH or S\n"); return 2; }

    std::string cfg = "threads=" + std::to_string(threads);
    RTCDevice dev = rtcNewDevice(cfg.c_str());
    if (!dev) { std::fprintf(stderr, "rtcNewDevice failed\n"); return 1; }
    std::printf("Embree %s, native ray16 support %lld, %s mode, %d threads, %d warm-up + %d timed frames,"
                " build quality %s\n", RTC_VERSION_STRING,
                (long long)rtcGetDeviceProperty(dev, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED),
                mode == "packet" ? "packet (rtcOccluded16)" : "single (rtcOccluded1)", threads, warmup, frames,
                quality.c_str());
    RTCBuildQuality q = quality == "high" ? RTC_BUILD_QUALITY_HIGH
                        : quality == "low" ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM;
    auto b0 = std::chrono::steady_clock::now();
    RTCScene rs = rtcNewScene(dev);
    rtcSetSceneBuildQuality(rs, q);
    { // floor: two triangles
        RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *vb = (float *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                     3 * sizeof(float), 4);
        float H = (float)FLOOR_HALF, Y = (float)FLOOR_Y;
        float v[12] = {-H, Y, -H, H, Y, -H, H, Y, H, -H, Y, H};
        std::memcpy(vb, v, sizeof v);
        unsigned *ib = (unsigned *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                          3 * sizeof(unsigned), 2);
        unsigned idx[6] = {0, 1, 2, 0, 2, 3};
        std::memcpy(ib, idx, sizeof idx);
        rtcCommitGeometry(g);
        sc.floorGeom = rtcAttachGeometry(rs, g);
        rtcReleaseGeometry(g);
    }
    if (!sc.tris.empty()) {
        RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(g, q);
        float *vb = (float *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                     3 * sizeof(float), sc.verts.size());
        for (size_t i = 0; i < sc.verts.size(); ++i) {
            vb[3 * i] = (float)sc.verts[i].x; vb[3 * i + 1] = (float)sc.verts[i].y; vb[3 * i + 2] = (float)sc.verts[i].z;
        }
        unsigned *ib = (unsigned *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                          3 * sizeof(unsigned), sc.tris.size() / 3);
        std::memcpy(ib, sc.tris.data(), sc.tris.size() * sizeof(unsigned));
        rtcCommitGeometry(g);
        sc.meshGeom = rtcAttachGeometry(rs, g);
        rtcReleaseGeometry(g);
    }
    if (!sc.sphereC.empty() && spheres == "point") {
        RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        float *vb = (float *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                     4 * sizeof(float), sc.sphereC.size());
        for (size_t i = 0; i < sc.sphereC.size(); ++i) {
            vb[4 * i] = (float)sc.sphereC[i].x; vb[4 * i + 1] = (float)sc.sphereC[i].y;
            vb[4 * i + 2] = (float)sc.sphereC[i].z; vb[4 * i + 3] = (float)sc.sphereR[i];
        }
        rtcCommitGeometry(g);
        sc.sphereGeom = rtcAttachGeometry(rs, g);
        rtcReleaseGeometry(g);
    } else if (!sc.sphereC.empty()) {
        RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, sc.sphereC.size());
        rtcSetGeometryUserData(g, &sc);
        rtcSetGeometryBoundsFunction(g, sphereBounds, nullptr);
        rtcSetGeometryIntersectFunction(g, sphereIntersect);
        rtcSetGeometryOccludedFunction(g, sphereOccluded);
        rtcCommitGeometry(g);
        sc.sphereGeom = rtcAttachGeometry(rs, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(rs);
    double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - b0).count();
    std::printf("%s: %zu mesh triangles + 2 floor triangles%s, build %.3f s\n", sceneName.c_str(), sc.tris.size() / 3,
                sc.sphereC.empty() ? "" : spheres == "point" ? " + 3 RTC_GEOMETRY_TYPE_SPHERE_POINT spheres" : " + 3 user-geometry spheres", build);

    if (!rayFile.empty()) {
        timeRayFile(rayFile.c_str(), mode, rs, threads, warmup, frames);
        rtcReleaseScene(rs);
        rtcReleaseDevice(dev);
        return 0;
    }
    Renderer r{sc, rs, mode == "packet"};
    r.factor.assign((size_t)SIZE * SIZE, 0);
    r.grey.assign((size_t)SIZE * SIZE, 0);
    std::vector<double> secs;
    Result last;
    for (int f = 0; f < warmup + frames; ++f) {
        auto t0 = std::chrono::steady_clock::now();
        last = r.frame(threads, f);
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (f >= warmup) secs.push_back(s);
        std::printf("frame %d%s: %.4f s, %lld shadow rays\n", f, f < warmup ? " (warm-up)" : "", s, last.shadowRays);
    }
    double med = median(secs);
    std::printf("RESULT scene=%s mode=%s triangles=%zu primary_hits=%lld lit_points=%lld shadow_rays_per_frame=%lld"
                " median_s=%.4f frames_s=", sceneName.c_str(), mode.c_str(), sc.tris.size() / 3, last.primaryHits,
                last.litPoints, last.shadowRays, med);
    for (size_t k = 0; k < secs.size(); ++k) std::printf("%s%.4f", k ? "," : "", secs[k]);
    std::printf(" Mshadow_rays_per_s=%.2f ns_per_shadow_ray_thread_time=%.1f\n", last.shadowRays / med / 1e6,
                threads * med * 1e9 / last.shadowRays);
    if (!image.empty()) writePgm(image.c_str(), r.grey);
    rtcReleaseScene(rs);
    rtcReleaseDevice(dev);
    return 0;
}
