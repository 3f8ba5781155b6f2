package geometries;

import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * A single body with a surface: it has an emission colour, a material and a normal at each point.
 */
public abstract class Geometry extends Intersectable {
    private Color emission = Color.BLACK;
    private Material material = new Material();

    /**
     * The unit normal of the surface at a point on it.
     *
     * @param point a point on the surface
     * @return the outward unit normal there
     */
    public abstract Vector getNormal(Point3D point);

    /** @return the emission colour (black by default) */
    public Color getEmission() {
        return emission;
    }

    /**
     * Sets the emission colour.
     *
     * @param emission the colour the body emits
     * @return this geometry
     */
    public Geometry setEmission(Color emission) {
        this.emission = requireNonNull(emission, "emission colour");
        return this;
    }

    /** @return the material (all factors 0 by default) */
    public Material getMaterial() {
        return material;
    }

    /**
     * Sets the material.
     *
     * @param material the surface properties
     * @return this geometry
     */
    public Geometry setMaterial(Material material) {
        this.material = requireNonNull(material, "material");
        return this;
    }
}
