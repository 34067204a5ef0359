namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Starting points for common soft materials, in SI units and the stable Neo-Hookean model.
    /// Real materials span wide ranges (the sources give ranges, not one number); each preset
    /// takes a representative value inside the range. The seed article's "jelly: mu 200-500,
    /// lambda 1000-3000" style numbers are unitless tuning values, not moduli, and are not used.
    /// Poisson ratios of nearly incompressible materials are capped at 0.49: lambda/mu is then
    /// already 50, and a stiffer bulk only costs solver iterations without a visible difference.
    /// </summary>
    public static class MaterialPresets
    {
        /// <summary>
        /// Gelatin dessert jelly: E = 1e4 Pa, nu = 0.49, 1030 kg/m^3.
        /// Gelatin gels at a few percent by weight measure E of 1e3-1e5 Pa in indentation and
        /// compression tests (e.g. Czerner et al. 2015, "Determination of elastic modulus of
        /// gelatin gels by indentation experiments", Procedia Materials Science 8); a hydrogel is
        /// mostly water, so nearly incompressible and about as dense as water.
        /// </summary>
        public static NeoHookeanMaterial Jelly => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e4f, 0.49f, 1030f);

        /// <summary>
        /// Soft vulcanised rubber: E = 2e6 Pa, nu = 0.49, 1100 kg/m^3.
        /// Rubber's shear modulus is of order 0.2-1 MPa, E = 3 G (Treloar, "The Physics of Rubber
        /// Elasticity", 3rd ed. 1975); its bulk modulus (~2 GPa) makes nu about 0.4999, capped
        /// here. 1100 kg/m^3 is the usual table value for soft commercial rubber (natural rubber
        /// gum is 930, filled compounds 1100-1200).
        /// </summary>
        public static NeoHookeanMaterial Rubber => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 2e6f, 0.49f, 1100f);

        /// <summary>
        /// Woven apparel fabric, for shells about 0.5 mm thick: E = 1e6 Pa, nu = 0.3, 400 kg/m^3.
        /// Fabric's effective in-plane modulus (tensile stiffness per unit width over thickness)
        /// is of order 1e5-1e7 Pa at small strain and in-plane Poisson ratios 0.1-0.4
        /// (Kawabata Evaluation System data, Kawabata 1980, "The Standardization and Analysis of
        /// Hand Evaluation"); 400 kg/m^3 at 0.5 mm gives 0.2 kg/m^2, a shirting-to-denim weight.
        /// </summary>
        public static NeoHookeanMaterial Cloth => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, 0.3f, 400f);

        /// <summary>
        /// Toy slime (PVA-borax gel): E = 1e3 Pa, nu = 0.49, 1050 kg/m^3.
        /// Oscillatory rheometry of PVA-borax gels gives a plateau storage modulus G' of order
        /// 1e2-1e3 Pa, so E = 3 G' of order 1e3 Pa; the gel is mostly water. Real slime flows
        /// (it is viscoelastic): pair this preset with damping and <see cref="SoftPlasticity"/>.
        /// </summary>
        public static NeoHookeanMaterial Slime => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e3f, 0.49f, 1050f);

        /// <summary>
        /// Soft tissue (fat and relaxed muscle): E = 2e4 Pa, nu = 0.49, 1060 kg/m^3.
        /// Tissue moduli span 1e3-1e5 Pa (reviews: McKee et al. 2011, "Indentation versus tensile
        /// measurements of Young's modulus for soft biological tissues", Tissue Eng. B 17(3);
        /// Wells and Liang 2011, J. R. Soc. Interface 8); tissue is nearly incompressible, and
        /// ICRP reference soft tissue has a density of 1030-1060 kg/m^3.
        /// </summary>
        public static NeoHookeanMaterial SoftTissue => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 2e4f, 0.49f, 1060f);
    }
}
