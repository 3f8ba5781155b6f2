package geometries;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Vector;

/**
 * A hit on a {@link TriangleMesh}: the point, the mesh and the triangle of the mesh the point lies on;
 * its normal, shadow point and surface coordinates are found from that triangle when shading asks.
 */
public final class MeshPoint extends GeoPoint {
    /** The index of the triangle hit, in the mesh's order. */
    public final int triangle;
    /** The barycentric weights of the triangle's vertices at the point, found when first needed. */
    private double[] weights;

    /**
     * Pairs a mesh and one of its triangles with a point on it.
     *
     * @param mesh     the mesh
     * @param triangle the triangle's index
     * @param point    the point on it
     */
    MeshPoint(TriangleMesh mesh, int triangle, Point3D point) {
        super(mesh, point);
        this.triangle = triangle;
    }

    /** {@return the unit normal of the triangle hit, or on a smooth mesh the smooth normal at the point} */
    @Override
    public Vector getNormal() {
        TriangleMesh mesh = (TriangleMesh) geometry;
        return mesh.isSmooth() ? mesh.shading().normal(triangle, weights()) : mesh.getNormal(triangle);
    }

    /**
     * {@inheritDoc} On a smooth mesh, the point lifted onto the tangent planes of the triangle's
     * vertices that it lies below, seen from the light's side (see {@link MeshShading}).
     */
    @Override
    public Point3D getShadowPoint(Vector l) {
        TriangleMesh mesh = (TriangleMesh) geometry;
        return mesh.isSmooth() ? mesh.shading().shadowPoint(triangle, weights(), point, l) : point;
    }

    /** {@return on a smooth mesh the unit normal of the triangle hit, else null} */
    @Override
    public Vector getFaceNormal() {
        TriangleMesh mesh = (TriangleMesh) geometry;
        return mesh.isSmooth() ? mesh.getNormal(triangle) : null;
    }

    /** {@return the UVs of the triangle's vertices mixed by the point's barycentric weights} */
    @Override
    public double[] getUV() {
        return ((TriangleMesh) geometry).shading().uv(triangle, weights());
    }

    /** {@return the barycentric weights of the triangle's vertices at the point} */
    private double[] weights() {
        if (weights == null)
            weights = ((TriangleMesh) geometry).shading().weights(triangle, point);
        return weights;
    }

    @Override
    public String toString() {
        return "MeshPoint{triangle " + triangle + " of " + geometry + " at " + point + "}";
    }
}
