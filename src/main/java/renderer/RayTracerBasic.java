package renderer;

import accel.BoundingVolumeHierarchy;
import geometries.Intersectable.GeoPoint;
import accel.ShadowFrustum;
import geometries.Triangle;
import geometries.TriangleMesh;
import lighting.AreaLightSource;
import lighting.LightSource;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

import static primitives.Util.alignZero;

/**
 * The course's ray tracer: Phong local lighting with shadows that let light through transparent
 * bodies, plus reflection and straight-through refraction traced recursively.
 */
public class RayTracerBasic extends RayTracerBase {
    /** The deepest recursion of reflected and refracted rays. */
    private static final int MAX_CALC_COLOR_LEVEL = 10;
    /** Rays whose accumulated factor falls below this are not traced. */
    private static final double MIN_CALC_COLOR_K = 0.001;
    private static final double INITIAL_K = 1.0;
    /** The grid of one jittered spread ray: a glossy or blurry surface met inside another's beam. */
    private static final JitteredGrid SINGLE_SPREAD_RAY = new JitteredGrid(1);

    private volatile BoundingVolumeHierarchy accelerator;
    private boolean bruteForce;

    /**
     * Creates a ray tracer for a scene.
     *
     * @param scene the scene
     */
    public RayTracerBasic(Scene scene) {
        super(scene);
    }

    /**
     * {@inheritDoc} The calling thread's state is looked up once here and passed down to every
     * intersection, light and spread ray of the path.
     */
    @Override
    public Color traceRay(Ray ray) {
        ThreadState state = threadState();
        GeoPoint closestPoint = findClosestIntersection(ray, state);
        return closestPoint == null ? scene.background : calcColor(closestPoint, ray, state);
    }

    private GeoPoint findClosestIntersection(Ray ray, ThreadState state) {
        BoundingVolumeHierarchy bvh = accelerator();
        return bvh.closestHit(ray, state.query(bvh));
    }

    /** Builds the bounding volume hierarchy over the scene's bodies, on the calling thread, unless it is up to date. */
    @Override
    protected void prepare() {
        prepare(1);
    }

    /**
     * Builds the bounding volume hierarchy over the scene's bodies on up to a number of threads,
     * unless it was built over them as they are now: the scene's composite is the same object and
     * no body was added to it (or to a composite in it) since.
     */
    @Override
    protected synchronized void prepare(int threads) {
        BoundingVolumeHierarchy bvh = accelerator;
        if (bvh == null || !bvh.isBuiltFrom(scene.geometries))
            accelerator = bruteForce ? BoundingVolumeHierarchy.scan(scene.geometries)
                    : BoundingVolumeHierarchy.build(scene.geometries, threads);
    }

    /**
     * Makes the tracer test every body on every ray instead of walking the hierarchy: the reference
     * the hierarchy is checked against.
     *
     * @param bruteForce true for a linear scan of the bodies
     */
    synchronized void setBruteForce(boolean bruteForce) {
        this.bruteForce = bruteForce;
        accelerator = null;
        prepare();
    }

    /** {@return the hierarchy, built on first use when no render has prepared it} */
    BoundingVolumeHierarchy accelerator() {
        BoundingVolumeHierarchy bvh = accelerator;
        if (bvh == null) {
            prepare();
            bvh = accelerator;
        }
        return bvh;
    }

    /** The colour at a point seen by a primary ray: the recursive colour plus the ambient light. */
    private Color calcColor(GeoPoint geoPoint, Ray ray, ThreadState state) {
        return calcColor(geoPoint, ray, MAX_CALC_COLOR_LEVEL, INITIAL_K, state)
                .add(scene.ambientLight.getIntensity());
    }

    private Color calcColor(GeoPoint geoPoint, Ray ray, int level, double k, ThreadState state) {
        Vector n = geoPoint.getNormal();
        Color color = geoPoint.geometry.getEmission().add(calcLocalEffects(geoPoint, ray.getDir(), n, k, state));
        if (level == 1)
            return color;
        Color global = calcGlobalEffects(geoPoint, ray.getDir(), n, level, k, state);
        // adding black would give the same components (a sum of non-negative ones is never −0)
        return global == Color.BLACK ? color : color.add(global);
    }

    /**
     * Diffuse and specular light from every light source that reaches the point. The sum is kept in
     * raw components, with the same arithmetic as adding the lights' {@link Color}s: each light's
     * intensity scaled by its transparency, then by the diffuse and the specular factor, both added.
     */
    private Color calcLocalEffects(GeoPoint geoPoint, Vector v, Vector n, double k, ThreadState state) {
        double nv = alignZero(n.dotProduct(v));
        if (nv == 0)
            return Color.BLACK;
        Material material = geoPoint.geometry.getMaterial();
        double r = 0;
        double g = 0;
        double b = 0;
        for (LightSource light : scene.lights) {
            Vector l = light.getL(geoPoint.point);
            double nl = alignZero(n.dotProduct(l));
            if (nl * nv > 0) { // the light and the viewer are on the same side of the surface
                double ktr = transparency(light, l, n, geoPoint, state);
                if (ktr * k > MIN_CALC_COLOR_K) {
                    Color intensity = light.getIntensity(geoPoint.point);
                    double kd = calcDiffusive(material, nl);
                    double ks = calcSpecular(material, n, l, nl, v);
                    double lightR = scaled(intensity.getR(), ktr);
                    double lightG = scaled(intensity.getG(), ktr);
                    double lightB = scaled(intensity.getB(), ktr);
                    r = r + scaled(lightR, kd) + scaled(lightR, ks);
                    g = g + scaled(lightG, kd) + scaled(lightG, ks);
                    b = b + scaled(lightB, kd) + scaled(lightB, ks);
                }
            }
        }
        // the components are sums of non-negative terms: kept at the largest double at the end, as after each sum
        return new Color(Math.min(r, Double.MAX_VALUE), Math.min(g, Double.MAX_VALUE), Math.min(b, Double.MAX_VALUE));
    }

    /** A colour component scaled as {@link Color#scale(double)} scales it: an overflow kept at the largest double. */
    private static double scaled(double component, double factor) {
        return Math.min(component * factor, Double.MAX_VALUE);
    }

    /** {@return the diffuse factor of a light: kD · |n·l|} */
    private double calcDiffusive(Material material, double nl) {
        return material.getKd() * Math.abs(nl);
    }

    /** {@return the specular factor of a light: kS · max(0, −v·r)^nShininess, 0 when there is no highlight} */
    private double calcSpecular(Material material, Vector n, Vector l, double nl, Vector v) {
        // r = l − 2(l·n)n
        double minusVR = -alignZero(v.dotProduct(l) - 2 * nl * v.dotProduct(n));
        return minusVR <= 0 ? 0 : material.getKs() * Math.pow(minusVR, material.getShininess());
    }

    /**
     * Reflected and refracted light, each traced while its factor stays above the limit: one sharp
     * ray each from a mirror and clear glass, spread rays from glossy ({@code kG}) and blurry
     * ({@code kB}) materials.
     */
    private Color calcGlobalEffects(GeoPoint geoPoint, Vector v, Vector n, int level, double k, ThreadState state) {
        Material material = geoPoint.geometry.getMaterial();
        Color color = Color.BLACK;
        double kR = material.getKr();
        double kkr = k * kR;
        if (kkr > MIN_CALC_COLOR_K)
            color = calcSpreadEffect(geoPoint.point, constructReflectedRay(geoPoint.point, v, n), n,
                    material.getKg(), level, kR, kkr, state);
        double kT = material.getKt();
        double kkt = k * kT;
        if (kkt > MIN_CALC_COLOR_K)
            color = color.add(calcSpreadEffect(geoPoint.point, constructRefractedRay(geoPoint.point, v, n), n,
                    material.getKb(), level, kT, kkt, state));
        return color;
    }

    /**
     * The light along a sharp reflected or refracted ray, or, when the material spreads it, the
     * average over rays through the {@link SpreadSquare} around it. The first spreading surface of a
     * path traces the tracer's gloss grid, {@code sqrtGlossRays²} jittered rays; a spreading surface
     * met by one of those rays traces one jittered ray, so a pixel's rays grow linearly with the
     * recursion's depth, and the beam's average still takes in every surface's spread.
     *
     * @param point    the surface point
     * @param sharpRay the sharp reflected or refracted ray
     * @param n        the surface normal at the point
     * @param spread   the material's kG or kB: the half-edge of the square at unit distance
     * @param level    the recursion level of the point
     * @param kx       the material's kR or kT
     * @param kkx      the accumulated factor of the reflected or refracted light
     * @param state    the calling thread's state
     * @return the reflected or refracted colour, scaled by kx
     */
    private Color calcSpreadEffect(Point3D point, Ray sharpRay, Vector n, double spread, int level, double kx,
                                   double kkx, ThreadState state) {
        if (spread == 0)
            return calcGlobalEffect(sharpRay, level, kx, kkx, state);
        SpreadSquare square = new SpreadSquare(point, sharpRay, n, spread);
        if (state.inSpreadBeam) {
            double[] sample = state.spreadPoint();
            SINGLE_SPREAD_RAY.sampleUnchecked(state.random, sample);
            ++state.spreadRays;
            return calcGlobalEffect(square.ray(sample[0], sample[1]), level, kx, kkx, state);
        }
        return calcSpreadBeam(square, level, kx, kkx, state);
    }

    /**
     * The average light along the rays through the jittered points of the tracer's gloss grid on a
     * spread square. While they are traced, the spreading surfaces they meet spread one ray each.
     *
     * @param square the square around the sharp ray
     * @param level  the recursion level of the surface point
     * @param kx     the material's kR or kT
     * @param kkx    the accumulated factor of the reflected or refracted light
     * @param state  the calling thread's state
     * @return the average colour, scaled by kx
     */
    private Color calcSpreadBeam(SpreadSquare square, int level, double kx, double kkx, ThreadState state) {
        JitteredGrid grid = getGlossGrid();
        int count = grid.getSamplesCount();
        double[] samples = state.spreadPoints(grid);
        grid.sampleUnchecked(state.random, samples);
        state.spreadRays += count;
        state.inSpreadBeam = true;
        try {
            double r = 0;
            double g = 0;
            double b = 0;
            for (int s = 0; s < count; ++s) {
                Color color = traceSecondary(square.ray(samples[2 * s], samples[2 * s + 1]), level, kkx, state);
                r += color.getR();
                g += color.getG();
                b += color.getB();
            }
            double scale = kx / count;
            return new Color(r * scale, g * scale, b * scale);
        } finally {
            state.inSpreadBeam = false;
        }
    }

    private Color calcGlobalEffect(Ray ray, int level, double kx, double kkx, ThreadState state) {
        return traceSecondary(ray, level, kkx, state).scale(kx);
    }

    /** The colour a reflected, refracted or spread ray sees, one level down: the background when it hits nothing. */
    private Color traceSecondary(Ray ray, int level, double kkx, ThreadState state) {
        GeoPoint geoPoint = findClosestIntersection(ray, state);
        return geoPoint == null ? scene.background : calcColor(geoPoint, ray, level - 1, kkx, state);
    }

    private Ray constructReflectedRay(Point3D point, Vector v, Vector n) {
        double vn = v.dotProduct(n);
        Vector r = vn == 0 ? v : v.subtract(n.scale(2 * vn));
        return new Ray(point, r, n);
    }

    private Ray constructRefractedRay(Point3D point, Vector v, Vector n) {
        return new Ray(point, v, n);
    }

    /**
     * How much of a light reaches a point: 1 when nothing is in the way, 0 when an opaque body is,
     * and the product of the {@code kT} of the transparent bodies in between otherwise. With soft
     * shadows on and a light with an area, the average over rays to the light's square. Nothing is
     * allocated: the rays live in the calling thread's {@link LightSquare}.
     *
     * @param light    the light
     * @param l        the unit direction from the light to the point
     * @param n        the surface normal at the point
     * @param geoPoint the lit point
     * @param state    the calling thread's state
     * @return the transparency factor in [0, 1]
     */
    double transparency(LightSource light, Vector l, Vector n, GeoPoint geoPoint, ThreadState state) {
        BoundingVolumeHierarchy bvh = accelerator();
        Point3D point = geoPoint.point;
        // the ray to the light itself, or to the centre of its square
        LightSquare square = state.lightSquare().setPoint(point, n, l, bvh, state.query(bvh))
                .setFacet(geoPoint.geometry instanceof TriangleMesh || geoPoint.geometry instanceof Triangle);
        double distance = light.getDistance(point);
        if (isSoftShadows() && light instanceof AreaLightSource areaLight && areaLight.getEdges() > 0)
            return calcSoftShadows(areaLight, square, distance, state);
        ++state.shadowRays;
        return square.visibility(distance);
    }

    /**
     * The soft-shadow factor of a light with an area: the ray to the centre of the light's square and
     * one to a jittered point in each cell of its {@code sqrtBeamNum × sqrtBeamNum} grid, averaged.
     * With adaptive sampling, the grid's outline is traced first and the inner cells only when its
     * rays and the centre's disagree.
     *
     * @param light          the light
     * @param square         the calling thread's light square, set at the lit point
     * @param centreDistance the distance from the point to the centre of the light's square
     * @param state          the calling thread's state
     * @return the average transparency of the rays, in [0, 1]
     */
    double calcSoftShadows(AreaLightSource light, LightSquare square, double centreDistance, ThreadState state) {
        square.setSquare(light);
        JitteredGrid grid = getBeamGrid();
        double[] samples = state.points(grid);
        if (square.isSettled()) // the points are not needed, but the numbers drawn after them must stay the same
            state.random.skip(2L * grid.getSamplesCount());
        else
            grid.sampleUnchecked(state.random, samples);
        int outline = grid.getOutlineCount();
        double ktr = square.visibility(centreDistance, samples, outline);
        int rays = 1 + outline;
        boolean agree = ktr == 0 || ktr == rays;
        if (!(isAdaptiveSoftShadows() && agree)) {
            ktr += square.visibility(samples, outline, grid.getSamplesCount());
            rays = 1 + grid.getSamplesCount();
        }
        state.shadowRays += rays;
        if (square.isOpen())
            state.openShadowRays += rays;
        if (square.isBlocked())
            state.blockedShadowRays += rays;
        return ktr / rays;
    }

    /**
     * A light's square as seen from a lit point, in raw doubles: shadow rays to its sample points are
     * traced without allocating anything. Each rendering thread keeps one ({@link ThreadState}) and
     * sets it again for every lit point and light. The rays are traced as one bundle: the bodies
     * that may block any of them are gathered once, by the pyramid from the point to the square, and
     * the rays are tested against those alone (together, as a packet, when a subtree of many was
     * kept); when none may, no ray needs testing.
     */
    static final class LightSquare {
        /**
         * How far, relative to the reach of the square, the square must lie off the point's tangent
         * plane for all its rays to leave the surface on the same side.
         */
        private static final double SIDE_MARGIN = 1e-6;

        /** How the rays of a bundle are traced. */
        private enum Bundle {
            /** Nothing can block any of them: each lets all the light through, untested. */
            OPEN,
            /** A closed opaque mesh lies across every one of them: each is blocked, untested. */
            BLOCKED,
            /** Each is tested against the few bodies gathered for the bundle. */
            GATHERED,
            /** The bundle kept a subtree: its rays walk it together, as a packet. */
            PACKET,
            /** The bundle's pyramid is flat, or there is no square: each walks the whole hierarchy. */
            WHOLE
        }

        private double cx;
        private double cy;
        private double cz;
        private double ux;
        private double uy;
        private double uz;
        private double vx;
        private double vy;
        private double vz;
        private double edges;
        /** The lit point. */
        private Point3D point;
        private double px;
        private double py;
        private double pz;
        /** The normal scaled to the length DELTA: how far a shadow ray's head moves off the surface. */
        private double nx;
        private double ny;
        private double nz;
        /** The ray to the light itself (or the centre of its square): its head, moved off the surface, and unit direction. */
        private double centreOx;
        private double centreOy;
        private double centreOz;
        private double centreDx;
        private double centreDy;
        private double centreDz;
        private BoundingVolumeHierarchy bvh;
        private BoundingVolumeHierarchy.Query query;
        private Bundle bundle = Bundle.WHOLE;
        /** Whether the lit point lies on a triangle (of a mesh, or a {@link Triangle}): see {@link #setFacet}. */
        private boolean facet;

        /**
         * Sets the lit point and the ray from it to the light (to the centre of the light's square),
         * the same ray as {@link Ray#Ray(Point3D, Vector, Vector)} makes from the point toward −l.
         * No square is set: until {@link #setSquare}, rays walk the whole hierarchy; the point is not
         * taken to lie on a triangle until {@link #setFacet} says so.
         *
         * @param p     the lit point
         * @param n     the surface normal at the point
         * @param l     the unit direction from the light to the point
         * @param bvh   the hierarchy of the scene
         * @param query the calling thread's scratch space for it
         * @return this light square
         */
        LightSquare setPoint(Point3D p, Vector n, Vector l, BoundingVolumeHierarchy bvh,
                             BoundingVolumeHierarchy.Query query) {
            double normalX = n.getX();
            double normalY = n.getY();
            double normalZ = n.getZ();
            double normalLength = n.length();
            double delta = Ray.DELTA / normalLength;
            this.point = p;
            this.px = p.getX();
            this.py = p.getY();
            this.pz = p.getZ();
            this.nx = normalX * delta;
            this.ny = normalY * delta;
            this.nz = normalZ * delta;
            this.bvh = bvh;
            this.query = query;
            this.bundle = Bundle.WHOLE;
            this.facet = false;
            double dirX = -l.getX();
            double dirY = -l.getY();
            double dirZ = -l.getZ();
            double side = alignZero(normalX * dirX + normalY * dirY + normalZ * dirZ);
            double move = side == 0 ? 0 : (side > 0 ? Ray.DELTA : -Ray.DELTA) / normalLength;
            this.centreOx = side == 0 ? px : px + normalX * move;
            this.centreOy = side == 0 ? py : py + normalY * move;
            this.centreOz = side == 0 ? pz : pz + normalZ * move;
            // l is a unit vector already: normalising again, as the ray does, moves at most its last bits
            double length = Math.sqrt(dirX * dirX + dirY * dirY + dirZ * dirZ);
            this.centreDx = dirX / length;
            this.centreDy = dirY / length;
            this.centreDz = dirZ / length;
            return this;
        }

        /**
         * Tells whether the lit point of the last {@link #setPoint} lies on a triangle (of a mesh, or a
         * {@link Triangle}). Only then is the surface around it set aside from the bundle's gather
         * ({@link accel.ShadowFrustum#setLeaving}): its neighbouring triangles are the bodies that
         * test serves, and the bundles of other points (a sphere's, a plane's) do without its cost.
         *
         * @param onTriangle whether the point lies on a triangle
         * @return this light square
         */
        LightSquare setFacet(boolean onTriangle) {
            this.facet = onTriangle;
            return this;
        }

        /**
         * Sets the light's square, seen from the point of the last {@link #setPoint}, and gathers
         * the bodies its bundle of rays may meet.
         *
         * @param light the light
         */
        void setSquare(AreaLightSource light) {
            Point3D center = light.getCenter();
            Vector u = light.getU(point);
            Vector v = light.getV(point);
            this.cx = center.getX();
            this.cy = center.getY();
            this.cz = center.getZ();
            this.ux = u.getX();
            this.uy = u.getY();
            this.uz = u.getZ();
            this.vx = v.getX();
            this.vy = v.getY();
            this.vz = v.getZ();
            this.edges = light.getEdges();
            this.bundle = gather();
        }

        /**
         * Gathers the bodies the bundle's rays may meet. When all the rays leave the surface on the
         * same side, they start at one point DELTA off the surface, the apex of their pyramid;
         * otherwise the pyramid starts at the point itself and is DELTA thick. For a point on a
         * triangle ({@link #setFacet}), the frustum is told the surface the rays leave, which lies
         * behind their starts ({@link accel.ShadowFrustum#setLeaving}).
         *
         * @return how the bundle's rays are to be traced
         */
        private Bundle gather() {
            double half = edges / 2;
            double ax = ux * half;
            double ay = uy * half;
            double az = uz * half;
            double bx = vx * half;
            double by = vy * half;
            double bz = vz * half;
            double wx = cx - px;
            double wy = cy - py;
            double wz = cz - pz;
            // how far the centre and the corners c ± a ± b lie off the tangent plane, times DELTA
            double centre = nx * wx + ny * wy + nz * wz;
            double spread = Math.abs(nx * ax + ny * ay + nz * az) + Math.abs(nx * bx + ny * by + nz * bz);
            double margin = SIDE_MARGIN * Ray.DELTA * (Math.sqrt(wx * wx + wy * wy + wz * wz) + edges);
            double side = centre - spread > margin ? 1 : centre + spread < -margin ? -1 : 0;
            double thickness = side == 0 ? Ray.DELTA : 0;
            ShadowFrustum frustum = query.getFrustum();
            if (!frustum.set(px + side * nx, py + side * ny, pz + side * nz, cx + side * nx, cy + side * ny,
                    cz + side * nz, ax, ay, az, bx, by, bz, thickness))
                return Bundle.WHOLE;
            if (facet)
                frustum.setLeaving((int) side, px, py, pz, nx, ny, nz);
            if (!bvh.gather(query))
                return Bundle.OPEN;
            if (bvh.blocksBundle(query))
                return Bundle.BLOCKED;
            return query.isSubtreeGathered() ? Bundle.PACKET : Bundle.GATHERED;
        }

        /** {@return true when no ray of the bundle can be blocked: each lets all the light through} */
        boolean isOpen() {
            return bundle == Bundle.OPEN;
        }

        /** {@return true when every ray of the bundle is blocked by a closed opaque mesh} */
        boolean isBlocked() {
            return bundle == Bundle.BLOCKED;
        }

        /** {@return true when the bundle's rays need no tracing: it is open, or blocked} */
        boolean isSettled() {
            return isOpen() || isBlocked();
        }

        /** {@return the summed transparency of some rays of a settled bundle: 1 each when open, else 0} */
        private double settled(int rays) {
            return isOpen() ? rays : 0;
        }

        /**
         * The transparency along the ray to the light (or to the centre of its square), traced alone.
         *
         * @param distance the distance from the point to the light (or the centre of its square)
         * @return the transparency in [0, 1]
         */
        double visibility(double distance) {
            if (isSettled())
                return settled(1);
            return transmittance(centreOx, centreOy, centreOz, centreDx, centreDy, centreDz, distance);
        }

        /** The transparency along one ray of the bundle, traced alone. */
        private double transmittance(double ox, double oy, double oz, double dx, double dy, double dz,
                                     double distance) {
            return bundle == Bundle.WHOLE
                    ? bvh.transmittance(ox, oy, oz, dx, dy, dz, distance, MIN_CALC_COLOR_K, query)
                    : bvh.gatheredTransmittance(ox, oy, oz, dx, dy, dz, distance, MIN_CALC_COLOR_K, query);
        }

        /**
         * The transparency along the ray to the centre of the square plus the summed transparency
         * of the rays to the first sample points: all traced as one packet when the bundle kept a
         * subtree, else one by one.
         *
         * @param distance the distance from the point to the centre of the square
         * @param samples  sample points in the unit square, as a {@link JitteredGrid} draws them
         * @param to       one past the last sample point
         * @return the centre's transparency plus the sum of the others'
         */
        double visibility(double distance, double[] samples, int to) {
            if (isSettled())
                return settled(1 + to);
            if (bundle != Bundle.PACKET)
                return visibility(distance) + traceSamples(samples, 0, to);
            query.clearPacket();
            query.addToPacket(centreOx, centreOy, centreOz, centreDx, centreDy, centreDz, distance);
            traceSamples(samples, 0, to);
            double samplesKtr = tracePacket(1);
            return query.getTransmittance(0) + samplesKtr;
        }

        /**
         * The summed transparency of the shadow rays to some of the sample points: traced as one
         * packet when the bundle kept a subtree, else one by one.
         *
         * @param samples sample points in the unit square, as a {@link JitteredGrid} draws them
         * @param from    the first sample point
         * @param to      one past the last sample point
         * @return the sum of the rays' transparencies
         */
        double visibility(double[] samples, int from, int to) {
            if (isSettled())
                return settled(to - from);
            if (bundle != Bundle.PACKET)
                return traceSamples(samples, from, to);
            query.clearPacket();
            traceSamples(samples, from, to);
            return tracePacket(0);
        }

        /**
         * Traces the shadow rays to some of the sample points one by one, or for a packet, adds them
         * to the query's packet. Like {@link Ray#Ray(Point3D, Vector, Vector)}, each ray starts DELTA
         * off the surface on the side it leaves to.
         *
         * @return the sum of the rays' transparencies (0 for a packet, not traced yet)
         */
        private double traceSamples(double[] samples, int from, int to) {
            double ktr = 0;
            for (int s = from; s < to; ++s) {
                double du = (0.5 - samples[2 * s]) * edges;
                double dv = (0.5 - samples[2 * s + 1]) * edges;
                double dx = cx + ux * du + vx * dv - px;
                double dy = cy + uy * du + vy * dv - py;
                double dz = cz + uz * du + vz * dv - pz;
                double distance = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double inverse = 1 / distance;
                dx *= inverse;
                dy *= inverse;
                dz *= inverse;
                double side = alignZero(nx * dx + ny * dy + nz * dz);
                double offset = side > 0 ? 1 : side < 0 ? -1 : 0;
                double ox = px + offset * nx;
                double oy = py + offset * ny;
                double oz = pz + offset * nz;
                if (bundle == Bundle.PACKET)
                    query.addToPacket(ox, oy, oz, dx, dy, dz, distance);
                else
                    ktr += transmittance(ox, oy, oz, dx, dy, dz, distance);
            }
            return ktr;
        }

        /**
         * Traces the rays of the query's packet together, through the subtree the bundle kept.
         *
         * @param from the first ray whose answer counts
         * @return the sum of the answers of the rays from that one on
         */
        private double tracePacket(int from) {
            bvh.gatheredTransmittances(MIN_CALC_COLOR_K, query);
            double ktr = 0;
            for (int r = from; r < query.getPacketSize(); ++r)
                ktr += query.getTransmittance(r);
            return ktr;
        }
    }
}
