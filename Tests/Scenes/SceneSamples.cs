namespace Fulcrum.Tests.Scenes
{
    /// <summary>Scene texts shared by the scene tests.</summary>
    static class SceneSamples
    {
        /// <summary>The example of DESIGN.md without the ball's mass (its material's density then gives it).</summary>
        public static readonly string DesignExample = DesignExampleVerbatim.Replace("\"mass\": 1.0, ", "");

        /// <summary>The example of DESIGN.md, verbatim.</summary>
        public const string DesignExampleVerbatim = @"{
  ""format"": ""fulcrum-scene/1"",
  ""gravity"": [0, -9.81, 0],
  ""timestep"": 0.0166667,
  ""solver"": { ""type"": ""tgs"", ""iterations"": 4, ""substeps"": 4 },
  ""materials"": { ""wood"": { ""friction"": 0.5, ""restitution"": 0.0, ""density"": 700 } },
  ""bodies"": [
    { ""name"": ""ground"", ""type"": ""static"", ""shape"": { ""type"": ""box"", ""halfExtents"": [50, 0.5, 50] },
      ""position"": [0, -0.5, 0] },
    { ""name"": ""ball"", ""type"": ""dynamic"", ""mass"": 1.0, ""material"": ""wood"",
      ""shape"": { ""type"": ""sphere"", ""radius"": 0.5 },
      ""position"": [0, 5, 0], ""rotation"": [0, 0, 0, 1], ""velocity"": [0, 0, 0],
      ""angularVelocity"": [0, 0, 0], ""ccd"": false }
  ],
  ""joints"": [ { ""name"": ""rope"", ""type"": ""distance"", ""bodyA"": ""ball"", ""bodyB"": null,
                ""anchorA"": [0, 0, 0], ""anchorB"": [0, 10, 0], ""minLength"": 0, ""maxLength"": 2 } ],
  ""softBodies"": [ { ""name"": ""jelly"", ""mesh"": { ""type"": ""box"", ""size"": [1, 1, 1], ""cells"": [4, 4, 4] },
                    ""material"": { ""model"": ""stable-neo-hookean"", ""youngsModulus"": 1e5,
                                  ""poissonRatio"": 0.45, ""density"": 1000 },
                    ""position"": [0, 2, 0], ""pinned"": [],
                    ""initialDeformation"": [[1,0,0],[0,1,0],[0,0,1]],
                    ""probes"": [[0, 0.5, 0], [0, -0.5, 0]] } ],
  ""generators"": [ { ""type"": ""tower"", ""count"": 20, ""size"": [1, 1, 1], ""at"": [0, 0, 0] } ]
}";

        /// <summary>Every field of the format at least once, with awkward floats.</summary>
        public const string Everything = @"{
  ""format"": ""fulcrum-scene/1"",
  ""gravity"": [0.1, -9.80665, 1e-7],
  ""timestep"": 0.008333333,
  ""solver"": { ""type"": ""pgs"", ""iterations"": 12, ""substeps"": 3 },
  ""materials"": {
    ""wood"": { ""friction"": 0.45, ""restitution"": 0.1, ""density"": 700 },
    ""ice"": { ""friction"": 0.02 },
    ""odd name"": { ""restitution"": 1 }
  },
  ""bodies"": [
    { ""name"": ""ground"", ""type"": ""static"", ""material"": ""ice"", ""shape"": { ""type"": ""plane"", ""normal"": [0, 1, 0], ""offset"": -0 }, ""position"": [0, 0, 0] },
    { ""name"": ""ramp"", ""type"": ""static"", ""shape"": { ""type"": ""mesh"", ""vertices"": [[0, 0, 0], [1, 0, 0], [0, 1, 1]], ""triangles"": [[0, 1, 2]] }, ""position"": [3, 0, 0] },
    { ""name"": ""rock"", ""type"": ""dynamic"", ""mass"": 2.5, ""shape"": { ""type"": ""convex"", ""points"": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]] },
      ""position"": [0, 1, 0], ""rotation"": [0, 0.38268343, 0, 0.9238795], ""velocity"": [1, 2, 3], ""angularVelocity"": [0.5, -0.25, 123456.789], ""ccd"": true },
    { ""name"": ""dumbbell"", ""material"": ""wood"", ""shape"": { ""type"": ""compound"", ""children"": [
        { ""shape"": { ""type"": ""sphere"", ""radius"": 0.3 }, ""position"": [-0.5, 0, 0] },
        { ""shape"": { ""type"": ""sphere"", ""radius"": 0.3 }, ""position"": [0.5, 0, 0], ""rotation"": [0, 0, 0.70710677, 0.70710677] },
        { ""shape"": { ""type"": ""capsule"", ""radius"": 0.1, ""halfHeight"": 0.5 } } ] },
      ""position"": [0, 4, 0] },
    { ""name"": ""lift"", ""type"": ""kinematic"", ""shape"": { ""type"": ""box"", ""halfExtents"": [1, 0.1, 1] }, ""position"": [5, 1, 0], ""velocity"": [0, 0.5, 0] }
  ],
  ""joints"": [
    { ""type"": ""ball"", ""name"": ""b"", ""bodyA"": ""rock"", ""bodyB"": ""dumbbell"", ""anchorA"": [0, 1, 0], ""anchorB"": [0, -1, 0], ""breakForce"": 1000 },
    { ""type"": ""hinge"", ""bodyA"": ""dumbbell"", ""bodyB"": null, ""anchorA"": [0, 0, 0], ""anchorB"": [0, 4, 0], ""axisA"": [0, 0, 1], ""axisB"": [0, 0, 1],
      ""lowerDeg"": -45, ""upperDeg"": 90, ""motorSpeed"": 1.5, ""maxMotorTorque"": 20, ""breakTorque"": 50 },
    { ""type"": ""distance"", ""bodyA"": null, ""bodyB"": ""rock"", ""anchorA"": [0, 10, 0], ""anchorB"": [0, 0, 0], ""minLength"": 0.5, ""maxLength"": 2, ""stiffnessHz"": 4, ""damping"": 0.7 },
    { ""type"": ""fixed"", ""bodyA"": ""rock"", ""bodyB"": ""tower/0"", ""anchorA"": [0, 0, 0], ""anchorB"": [0, 0, 0] },
    { ""type"": ""prismatic"", ""bodyA"": ""lift"", ""bodyB"": ""rock"", ""anchorA"": [0, 0, 0], ""anchorB"": [0, 0, 0], ""axisA"": [0, 1, 0], ""lower"": -1, ""upper"": 1 },
    { ""type"": ""coneTwist"", ""bodyA"": ""dumbbell"", ""bodyB"": ""rock"", ""anchorA"": [0, 0, 0], ""anchorB"": [0, 0, 0], ""axisA"": [1, 0, 0], ""axisB"": [1, 0, 0], ""coneDeg"": 30, ""twistDeg"": 10 }
  ],
  ""softBodies"": [
    { ""name"": ""jelly"", ""mesh"": { ""type"": ""box"", ""size"": [1, 0.5, 2], ""cells"": [2, 3, 4] },
      ""material"": { ""model"": ""neo-hookean"", ""mu"": 3000, ""lambda"": 20000, ""density"": 1100 },
      ""position"": [0, 3, 0], ""pinned"": [{ ""min"": [-0.5, 0.2, -1], ""max"": [0.5, 0.25, 1], ""to"": ""lift"" }, { ""min"": [0, 0, 0], ""max"": [0, 0, 0] }],
      ""initialDeformation"": [[1, 0.2, 0], [0, -1, 0], [0, 0, 1]], ""probes"": [[0, 0.25, 0]] },
    { ""name"": ""ball"", ""mesh"": { ""type"": ""sphere"", ""radius"": 0.3, ""cells"": 5 },
      ""material"": { ""youngsModulus"": 1e6, ""poissonRatio"": 0.49 }, ""position"": [2, 1, 0] },
    { ""name"": ""pill"", ""mesh"": { ""type"": ""capsule"", ""radius"": 0.2, ""halfHeight"": 0.35, ""cells"": 4 },
      ""material"": { ""youngsModulus"": 2e5, ""poissonRatio"": 0.3, ""density"": 900 }, ""position"": [4, 1, 0] },
    { ""name"": ""bar"", ""mesh"": { ""type"": ""beam"", ""length"": 1.7, ""thickness"": 0.1, ""cells"": 17 },
      ""material"": { ""youngsModulus"": 1e9, ""poissonRatio"": 0.3 }, ""position"": [6, 1, 0], ""pinned"": [{ ""min"": [-0.85, -1, -1], ""max"": [-0.85, 1, 1] }] },
    { ""name"": ""sheet"", ""mesh"": { ""type"": ""cloth"", ""size"": [1.5, 0.75], ""cells"": [6, 3], ""thickness"": 0.001, ""bendingScale"": 0.25 },
      ""material"": { ""youngsModulus"": 1e6, ""poissonRatio"": 0.3, ""density"": 300 }, ""position"": [8, 2, 0] },
    { ""name"": ""file-ball"", ""mesh"": { ""type"": ""tetgen"", ""node"": ""meshes/ball.node"", ""ele"": ""meshes/ball.ele"" },
      ""material"": { ""mu"": 1000, ""lambda"": 5000 } },
    { ""name"": ""sail"", ""mesh"": { ""type"": ""obj"", ""file"": ""C:\\sails\\jib.obj"", ""thickness"": 0.002, ""bendingScale"": 0 },
      ""material"": { ""youngsModulus"": 1e7, ""poissonRatio"": 0.2, ""density"": 800 } }
  ],
  ""generators"": [
    { ""type"": ""tower"", ""count"": 3, ""size"": [1, 0.5, 1], ""at"": [10, 0, 0], ""spacing"": 0.01, ""mass"": 2, ""material"": ""ice"" },
    { ""type"": ""pyramid"", ""name"": ""pyr"", ""count"": 4, ""axis"": ""z"", ""size"": [1, 1, 0.5], ""at"": [20, 0, 0], ""spacing"": 0.1 },
    { ""type"": ""wall"", ""count"": 5, ""rows"": 4, ""staggered"": false, ""axis"": ""x"", ""at"": [-10, 0, 0] },
    { ""type"": ""pile"", ""grid"": [2, 3, 2], ""shape"": ""capsule"", ""size"": [0.5, 1, 0.5], ""at"": [0, 0, 20], ""spacing"": 0.2 },
    { ""type"": ""chain"", ""count"": 5, ""anchor"": ""both"", ""at"": [0, 5, -20] },
    { ""type"": ""dominoes"", ""count"": 10, ""axis"": ""z"", ""tipSpeed"": 2, ""at"": [30, 0, 0], ""material"": ""wood"" }
  ]
}";

        /// <summary>A minimal valid scene with one body, for error tests to break.</summary>
        public static string OneBall(string bodyExtra = "", string shape = "{ \"type\": \"sphere\", \"radius\": 0.5 }") => $@"{{
  ""format"": ""fulcrum-scene/1"",
  ""materials"": {{ ""wood"": {{ ""friction"": 0.5, ""density"": 700 }} }},
  ""bodies"": [
    {{ ""name"": ""ball"", ""shape"": {shape}, ""position"": [0, 5, 0]{bodyExtra} }}
  ]
}}";
    }
}
