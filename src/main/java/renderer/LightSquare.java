package renderer;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import accel.ShadowFrustum;
import geometries.Triangle;
import lighting.AreaLightSource;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.alignZero;

/**
 * A light's square as seen from a lit point, in raw doubles: shadow rays to its sample points are
 * traced without allocating anything. Each rendering thread keeps one ({@link ThreadState}) and
 * sets it again for every lit point and light. The rays are traced as one bundle: the bodies
 * that may block any of them are gathered once, by the pyramid from the point to the square, and
 * the rays are tested against those alone (together, as a packet, when a subtree of many was
 * kept); when none may, no ray needs testing.
 */
final class LightSquare {
    /**
     * How far, relative to the reach of the square, the square must lie off the point's tangent
     * plane for all its rays to leave the surface on the same side.
     */
    private static final double SIDE_MARGIN = 1e-6;
    /** The order of no grid, until the first packet. */
    private static final PacketOrder NO_ORDER = new PacketOrder(new JitteredGrid(1), 0, false);

    /** How the rays of a bundle are traced. */
    private enum Bundle {
        /** Nothing can block any of them: each lets all the light through, untested. */
        OPEN,
        /** A closed opaque mesh lies across every one of them: each is blocked, untested. */
        BLOCKED,
        /** Each is tested against the few bodies gathered for the bundle. */
        GATHERED,
        /** The bundle kept a subtree, or an instance: its rays walk it together, as a packet. */
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
    /** The bundle's pyramid, as {@link ShadowFrustum#set} takes it: its apex, and its base's centre and half sides. */
    private final double[] apex = new double[3];
    private final double[] base = new double[9];
    private BoundingVolumeHierarchy bvh;
    private Query query;
    private Bundle bundle = Bundle.WHOLE;
    /** Whether the lit point lies on a triangle (of a mesh, or a {@link Triangle}): see {@link #setOnTriangle}. */
    private boolean onTriangle;
    /** The packet orders of the last grid: of all the rays, and of those inside the grid's outline. */
    private PacketOrder allOrder = NO_ORDER;
    private PacketOrder innerOrder = NO_ORDER;

    /**
     * Sets the lit point and the ray from it to the light (to the centre of the light's square),
     * the same ray as {@link Ray#Ray(Point3D, Vector, Vector)} makes from the point toward −l.
     * No square is set: until {@link #setSquare}, rays walk the whole hierarchy; the point is not
     * taken to lie on a triangle until {@link #setOnTriangle} says so.
     *
     * @param p     the lit point
     * @param n     the surface normal at the point
     * @param l     the unit direction from the light to the point
     * @param bvh   the hierarchy of the scene
     * @param query the calling thread's scratch space for it
     * @return this light square
     */
    LightSquare setPoint(Point3D p, Vector n, Vector l, BoundingVolumeHierarchy bvh,
                         Query query) {
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
        this.onTriangle = false;
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
    LightSquare setOnTriangle(boolean onTriangle) {
        this.onTriangle = onTriangle;
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
     * triangle ({@link #setOnTriangle}), the frustum is told the surface the rays leave, which lies
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
        setPyramid(side, ax, ay, az, bx, by, bz);
        if (!frustum.set(apex, base, thickness))
            return Bundle.WHOLE;
        if (onTriangle)
            frustum.setLeaving((int) side, px, py, pz, nx, ny, nz);
        if (!bvh.gather(query))
            return Bundle.OPEN;
        if (bvh.blocksBundle(query))
            return Bundle.BLOCKED;
        return query.isPacketTraced() ? Bundle.PACKET : Bundle.GATHERED;
    }

    /**
     * Sets the bundle's pyramid for {@link ShadowFrustum#set}: the apex at the point and the base at the
     * square, both moved off the surface to a side (or not, for side 0).
     *
     * @param side 1, −1 or 0: how many offsets n to move them by
     */
    private void setPyramid(double side, double ax, double ay, double az, double bx, double by, double bz) {
        apex[0] = px + side * nx;
        apex[1] = py + side * ny;
        apex[2] = pz + side * nz;
        base[0] = cx + side * nx;
        base[1] = cy + side * ny;
        base[2] = cz + side * nz;
        base[3] = ax;
        base[4] = ay;
        base[5] = az;
        base[6] = bx;
        base[7] = by;
        base[8] = bz;
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
    boolean isResolved() {
        return isOpen() || isBlocked();
    }

    /** {@return the summed transparency of some rays of a resolved bundle: 1 each when open, else 0} */
    private double resolved(int rays) {
        return isOpen() ? rays : 0;
    }

    /**
     * The transparency along the ray to the light (or to the centre of its square), traced alone.
     *
     * @param distance the distance from the point to the light (or the centre of its square)
     * @return the transparency in [0, 1]
     */
    double visibility(double distance) {
        if (isResolved())
            return resolved(1);
        return transmittance(centreOx, centreOy, centreOz, centreDx, centreDy, centreDz, distance);
    }

    /** The transparency along one ray of the bundle, traced alone. */
    private double transmittance(double ox, double oy, double oz, double dx, double dy, double dz,
                                 double distance) {
        query.setRay(ox, oy, oz, dx, dy, dz, distance);
        return bundle == Bundle.WHOLE ? bvh.transmittance(query, RayTracerBasic.MIN_CALC_COLOR_K)
                : bvh.bundleRayTransmittance(query, RayTracerBasic.MIN_CALC_COLOR_K);
    }

    /**
     * The transparency along the ray to the centre of the square plus the summed transparency of the
     * rays to the sample points of the grid's outline: all traced as one packet, the centre's first
     * and the others going round the outline, when the bundle kept a subtree, else one by one.
     *
     * @param distance the distance from the point to the centre of the square
     * @param samples  sample points in the unit square, as the grid draws them
     * @param grid     the light's grid
     * @return the centre's transparency plus the sum of the others'
     */
    double outlineVisibility(double distance, double[] samples, JitteredGrid grid) {
        int to = grid.getOutlineCount();
        if (isResolved())
            return resolved(1 + to);
        if (bundle != Bundle.PACKET)
            return visibility(distance) + traceSamples(samples, 0, to);
        query.clearPacket();
        query.addToPacket(centreOx, centreOy, centreOz, centreDx, centreDy, centreDz, distance);
        traceSamples(samples, 0, to);
        bvh.packetTransmittances(query, RayTracerBasic.MIN_CALC_COLOR_K);
        double samplesKtr = 0;
        for (int r = 1; r <= to; ++r)
            samplesKtr += query.getTransmittance(r);
        return query.getTransmittance(0) + samplesKtr;
    }

    /**
     * The transparency along the ray to the centre of the square plus the summed transparency of the
     * rays to every sample point, as {@link #outlineVisibility} plus {@link #innerVisibility} sum
     * them: traced as one packet, in {@link PacketOrder}, when the bundle kept a subtree.
     *
     * @param distance the distance from the point to the centre of the square
     * @param samples  sample points in the unit square, as the grid draws them
     * @param grid     the light's grid
     * @return the centre's transparency plus the sum of the others'
     */
    double visibility(double distance, double[] samples, JitteredGrid grid) {
        int outline = grid.getOutlineCount();
        if (bundle != Bundle.PACKET)
            return outlineVisibility(distance, samples, grid) + innerVisibility(samples, grid);
        if (!allOrder.isFor(grid))
            allOrder = new PacketOrder(grid, 0, true);
        tracePacket(allOrder, distance, samples);
        return (query.getTransmittance(allOrder.centrePlace()) + sum(allOrder, 0, outline))
                + sum(allOrder, outline, grid.getSamplesCount());
    }

    /**
     * The summed transparency of the shadow rays to the sample points inside the grid's outline:
     * traced as one packet, in {@link PacketOrder}, when the bundle kept a subtree, else one by one.
     *
     * @param samples sample points in the unit square, as the grid draws them
     * @param grid    the light's grid
     * @return the sum of the rays' transparencies
     */
    double innerVisibility(double[] samples, JitteredGrid grid) {
        int from = grid.getOutlineCount();
        int to = grid.getSamplesCount();
        if (isResolved())
            return resolved(to - from);
        if (bundle != Bundle.PACKET)
            return traceSamples(samples, from, to);
        if (!innerOrder.isFor(grid))
            innerOrder = new PacketOrder(grid, from, false);
        tracePacket(innerOrder, 0, samples);
        return sum(innerOrder, from, to);
    }

    /**
     * Fills the query's packet with the rays in an order, and traces them together, through the
     * subtree the bundle kept.
     */
    private void tracePacket(PacketOrder order, double distance, double[] samples) {
        query.clearPacket();
        for (int place = 0; place < order.size(); ++place) {
            int cell = order.rayAt(place);
            if (cell == PacketOrder.CENTRE)
                query.addToPacket(centreOx, centreOy, centreOz, centreDx, centreDy, centreDz, distance);
            else
                traceSample(samples, cell);
        }
        bvh.packetTransmittances(query, RayTracerBasic.MIN_CALC_COLOR_K);
    }

    /** {@return the summed answers of the packet's rays through cells [from, to), in visiting order} */
    private double sum(PacketOrder order, int from, int to) {
        double ktr = 0;
        for (int cell = from; cell < to; ++cell)
            ktr += query.getTransmittance(order.placeOf(cell));
        return ktr;
    }

    /**
     * Traces the shadow rays to some of the sample points one by one, or for a packet, adds them
     * to the query's packet.
     *
     * @return the sum of the rays' transparencies (0 for a packet, not traced yet)
     */
    private double traceSamples(double[] samples, int from, int to) {
        double ktr = 0;
        for (int s = from; s < to; ++s)
            ktr += traceSample(samples, s);
        return ktr;
    }

    /**
     * Traces the shadow ray to a sample point alone, or for a packet, adds it to the query's packet.
     * Like {@link Ray#Ray(Point3D, Vector, Vector)}, the ray starts DELTA off the surface on the side
     * it leaves to.
     *
     * @return the ray's transparency (0 for a packet, not traced yet)
     */
    private double traceSample(double[] samples, int s) {
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
        if (bundle != Bundle.PACKET)
            return transmittance(ox, oy, oz, dx, dy, dz, distance);
        query.addToPacket(ox, oy, oz, dx, dy, dz, distance);
        return 0;
    }
}
