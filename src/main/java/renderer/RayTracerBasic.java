package renderer;

import geometries.BoundingVolumeHierarchy;
import geometries.Intersectable.GeoPoint;
import geometries.ShadowFrustum;
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

    @Override
    public Color traceRay(Ray ray) {
        GeoPoint closestPoint = findClosestIntersection(ray);
        return closestPoint == null ? scene.background : calcColor(closestPoint, ray);
    }

    private GeoPoint findClosestIntersection(Ray ray) {
        BoundingVolumeHierarchy bvh = accelerator();
        return bvh.closestHit(ray, threadState().query(bvh));
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
    private Color calcColor(GeoPoint geoPoint, Ray ray) {
        return calcColor(geoPoint, ray, MAX_CALC_COLOR_LEVEL, INITIAL_K).add(scene.ambientLight.getIntensity());
    }

    private Color calcColor(GeoPoint geoPoint, Ray ray, int level, double k) {
        Vector n = geoPoint.getNormal();
        Color color = geoPoint.geometry.getEmission().add(calcLocalEffects(geoPoint, ray.getDir(), n, k));
        return level == 1 ? color : color.add(calcGlobalEffects(geoPoint, ray.getDir(), n, level, k));
    }

    /** Diffuse and specular light from every light source that reaches the point. */
    private Color calcLocalEffects(GeoPoint geoPoint, Vector v, Vector n, double k) {
        double nv = alignZero(n.dotProduct(v));
        if (nv == 0)
            return Color.BLACK;
        Material material = geoPoint.geometry.getMaterial();
        Color color = Color.BLACK;
        for (LightSource light : scene.lights) {
            Vector l = light.getL(geoPoint.point);
            double nl = alignZero(n.dotProduct(l));
            if (nl * nv > 0) { // the light and the viewer are on the same side of the surface
                double ktr = transparency(light, l, n, geoPoint);
                if (ktr * k > MIN_CALC_COLOR_K) {
                    Color lightIntensity = light.getIntensity(geoPoint.point).scale(ktr);
                    color = color.add(calcDiffusive(material, nl, lightIntensity),
                            calcSpecular(material, n, l, nl, v, lightIntensity));
                }
            }
        }
        return color;
    }

    private Color calcDiffusive(Material material, double nl, Color lightIntensity) {
        return lightIntensity.scale(material.getKd() * Math.abs(nl));
    }

    private Color calcSpecular(Material material, Vector n, Vector l, double nl, Vector v, Color lightIntensity) {
        // r = l − 2(l·n)n, and the highlight is max(0, −v·r)^nShininess
        double minusVR = -alignZero(v.dotProduct(l) - 2 * nl * v.dotProduct(n));
        if (minusVR <= 0)
            return Color.BLACK;
        return lightIntensity.scale(material.getKs() * Math.pow(minusVR, material.getShininess()));
    }

    /** Reflected and refracted light, each traced while its factor stays above the limit. */
    private Color calcGlobalEffects(GeoPoint geoPoint, Vector v, Vector n, int level, double k) {
        Material material = geoPoint.geometry.getMaterial();
        Color color = Color.BLACK;
        double kR = material.getKr();
        double kkr = k * kR;
        if (kkr > MIN_CALC_COLOR_K)
            color = calcGlobalEffect(constructReflectedRay(geoPoint.point, v, n), level, kR, kkr);
        double kT = material.getKt();
        double kkt = k * kT;
        if (kkt > MIN_CALC_COLOR_K)
            color = color.add(calcGlobalEffect(constructRefractedRay(geoPoint.point, v, n), level, kT, kkt));
        return color;
    }

    private Color calcGlobalEffect(Ray ray, int level, double kx, double kkx) {
        GeoPoint geoPoint = findClosestIntersection(ray);
        return (geoPoint == null ? scene.background : calcColor(geoPoint, ray, level - 1, kkx)).scale(kx);
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
     * shadows on and a light with an area, the average over rays to the light's square.
     *
     * @param light    the light
     * @param l        the unit direction from the light to the point
     * @param n        the surface normal at the point
     * @param geoPoint the lit point
     * @return the transparency factor in [0, 1]
     */
    double transparency(LightSource light, Vector l, Vector n, GeoPoint geoPoint) {
        ThreadState state = threadState();
        Point3D point = geoPoint.point;
        // the ray to the light itself, or to the centre of its square
        Ray lightRay = new Ray(point, l.scale(-1), n);
        double distance = light.getDistance(point);
        if (isSoftShadows() && light instanceof AreaLightSource areaLight && areaLight.getEdges() > 0)
            return calcSoftShadows(areaLight, lightRay, distance, n, point, state);
        ++state.shadowRays;
        return visibility(distance, lightRay, state);
    }

    /**
     * The soft-shadow factor of a light with an area: the ray to the centre of the light's square and
     * one to a jittered point in each cell of its {@code sqrtBeamNum × sqrtBeamNum} grid, averaged.
     * With adaptive sampling, the grid's outline is traced first and the inner cells only when its
     * rays and the centre's disagree.
     *
     * @param light          the light
     * @param centreRay      the shadow ray to the centre of the light's square
     * @param centreDistance the distance from the point to that centre
     * @param n              the surface normal at the point
     * @param point          the lit point
     * @param state          the calling thread's state
     * @return the average transparency of the rays, in [0, 1]
     */
    double calcSoftShadows(AreaLightSource light, Ray centreRay, double centreDistance, Vector n, Point3D point,
                           ThreadState state) {
        BoundingVolumeHierarchy bvh = accelerator();
        LightSquare square = new LightSquare(light, point, n, bvh, state.query(bvh));
        JitteredGrid grid = getBeamGrid();
        double[] samples = state.points(grid);
        if (square.isOpen()) // the points are not needed, but the numbers drawn after them must stay the same
            state.random.skip(2L * grid.getSamplesCount());
        else
            grid.sample(state.random, samples);
        double ktr = square.visibility(centreRay, centreDistance);
        int outline = grid.getOutlineCount();
        ktr += square.visibility(samples, 0, outline);
        int rays = 1 + outline;
        boolean agree = ktr == 0 || ktr == rays;
        if (!(isAdaptiveSoftShadows() && agree)) {
            ktr += square.visibility(samples, outline, grid.getSamplesCount());
            rays = 1 + grid.getSamplesCount();
        }
        state.shadowRays += rays;
        if (square.isOpen())
            state.openShadowRays += rays;
        return ktr / rays;
    }

    /**
     * A light's square as seen from a lit point, in raw doubles: shadow rays to its sample points are
     * traced without allocating anything. The rays are traced as one bundle: the bodies that may
     * block any of them are gathered once, by the pyramid from the point to the square, and each ray
     * is tested against those alone; when none may, no ray needs testing.
     */
    private static final class LightSquare {
        /**
         * How far, relative to the reach of the square, the square must lie off the point's tangent
         * plane for all its rays to leave the surface on the same side.
         */
        private static final double SIDE_MARGIN = 1e-6;

        /** How the rays of a bundle are traced. */
        private enum Bundle {
            /** Nothing can block any of them: each lets all the light through, untested. */
            OPEN,
            /** Each is tested against the bodies gathered for the bundle. */
            GATHERED,
            /** The bundle's pyramid is flat: each walks the whole hierarchy. */
            WHOLE
        }

        private final double cx;
        private final double cy;
        private final double cz;
        private final double ux;
        private final double uy;
        private final double uz;
        private final double vx;
        private final double vy;
        private final double vz;
        private final double edges;
        private final double px;
        private final double py;
        private final double pz;
        /** The normal scaled to the length DELTA: how far a shadow ray's head moves off the surface. */
        private final double nx;
        private final double ny;
        private final double nz;
        private final BoundingVolumeHierarchy bvh;
        private final BoundingVolumeHierarchy.Query query;
        private final Bundle bundle;

        LightSquare(AreaLightSource light, Point3D p, Vector n, BoundingVolumeHierarchy bvh,
                    BoundingVolumeHierarchy.Query query) {
            Point3D center = light.getCenter();
            Vector u = light.getU(p);
            Vector v = light.getV(p);
            double delta = Ray.DELTA / n.length();
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
            this.px = p.getX();
            this.py = p.getY();
            this.pz = p.getZ();
            this.nx = n.getX() * delta;
            this.ny = n.getY() * delta;
            this.nz = n.getZ() * delta;
            this.bvh = bvh;
            this.query = query;
            this.bundle = gather();
        }

        /**
         * Gathers the bodies the bundle's rays may meet. When all the rays leave the surface on the
         * same side, they start at one point DELTA off the surface, the apex of their pyramid;
         * otherwise the pyramid starts at the point itself and is DELTA thick.
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
            return bvh.gather(query) ? Bundle.GATHERED : Bundle.OPEN;
        }

        /** {@return true when no ray of the bundle can be blocked: each lets all the light through} */
        boolean isOpen() {
            return bundle == Bundle.OPEN;
        }

        /**
         * The transparency along the ray to the centre of the square.
         *
         * @param ray      the ray, its head already moved off the surface
         * @param distance the distance from the point to the centre
         * @return the transparency in [0, 1]
         */
        double visibility(Ray ray, double distance) {
            if (isOpen())
                return 1;
            Point3D p0 = ray.getP0();
            Vector dir = ray.getDir();
            return transmittance(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(), distance);
        }

        /** The transparency along one ray of the bundle. */
        private double transmittance(double ox, double oy, double oz, double dx, double dy, double dz,
                                     double distance) {
            return bundle == Bundle.WHOLE
                    ? bvh.transmittance(ox, oy, oz, dx, dy, dz, distance, MIN_CALC_COLOR_K, query)
                    : bvh.gatheredTransmittance(ox, oy, oz, dx, dy, dz, distance, MIN_CALC_COLOR_K, query);
        }

        /**
         * The summed transparency of the shadow rays to some of the sample points. Like
         * {@link Ray#Ray(Point3D, Vector, Vector)}, each ray starts DELTA off the surface on the side it
         * leaves to.
         *
         * @param samples sample points in the unit square, as a {@link JitteredGrid} draws them
         * @param from    the first sample point
         * @param to      one past the last sample point
         * @return the sum of the rays' transparencies
         */
        double visibility(double[] samples, int from, int to) {
            if (isOpen())
                return to - from;
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
                ktr += transmittance(px + offset * nx, py + offset * ny, pz + offset * nz, dx, dy, dz, distance);
            }
            return ktr;
        }
    }

    /**
     * The transparency along one shadow ray: the product of the {@code kT} of every body it passes
     * before the light, 0 as soon as that product drops below {@link #MIN_CALC_COLOR_K}.
     *
     * @param lightDistance the distance from the point to the light (or the light's sample point)
     * @param lightRay      the shadow ray, its head already moved off the surface
     * @param state         the calling thread's state (its query scratch space)
     * @return the transparency in [0, 1]
     */
    private double visibility(double lightDistance, Ray lightRay, ThreadState state) {
        BoundingVolumeHierarchy bvh = accelerator();
        Point3D p0 = lightRay.getP0();
        Vector dir = lightRay.getDir();
        return bvh.transmittance(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(), lightDistance,
                MIN_CALC_COLOR_K, state.query(bvh));
    }
}
