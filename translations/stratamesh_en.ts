<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
    <message>
        <source>StrataMesh is free software: you can redistribute it and/or modify it under the terms of the GNU Affero General Public License, version 3 or (at your option) any later version (AGPL-3.0-or-later). It comes with no warranty.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedral comparison meshes are made by TetGen 1.5 (Hang Si, WIAS Berlin), used under the AGPL-3.0; TetGen runs in a separate process.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built with Qt, VTK, CGAL, Eigen, OpenMesh, oneTBB, nanoflann and LBFGSpp.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About StrataMesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Conformal remeshing and analysis of 3D structural models, after J. Pellerin&apos;s PhD thesis. The menus offer:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DisabledReason</name>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>GuiOptions</name>
    <message>
        <source>StrataMesh: remeshing and meshing of 3D structural models.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User interface language: fr or en.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start with the box surfaces shown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start with triangle edges shown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model to open (same as --open).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown language &apos;%1&apos;: use fr or en.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the model or the project (.smproj) in &lt;file&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a number in [%2, %3], not &apos;%4&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown step &apos;%1&apos; for --run: use complexity, remesh, tetmesh or hybrid.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--sites must follow --run remesh or --run hybrid.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--cells must follow --run complexity.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown colouring &apos;%1&apos; for --colour-by: use entity, min-angle, quality or distance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--save-project needs a file name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load the model, do the steps, save the window as a PNG image in &lt;png&gt; and exit (status 0 when saved, 1 when the image could not be written, 2 when the model could not be opened, 3 when a step failed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Same as --run remesh --sites &lt;n&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Same as --run complexity --cells &lt;n&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Once the model is open, run &lt;step&gt;: complexity, remesh, tetmesh (the input and the remesh) or hybrid; may be repeated. The steps, --colour-by and --save-project are done in the order given, each once the one before has finished; a failed step stops the others, prints its name and exits with status 3 (after the screenshot, if asked).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of sites of the --run remesh or --run hybrid just before.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of cells of the --run complexity just before.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour both views by &lt;colouring&gt;: entity, min-angle, quality or distance (needs a remesh before).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the runs made so far as the project &lt;project&gt;.smproj.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the model could not be opened: no step was done.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ReviewCommand</name>
    <message>
        <source>Note on record %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accept record %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flag record %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reopen record %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ValidityMessages</name>
    <message>
        <source>… and %1 more problems of kind “%2”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model is not valid</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ClipControls</name>
    <message>
        <source>C&amp;lip plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only the cells on one side of a plane, to see inside the mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>North–south section (x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>East–west section (y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Horizontal section (z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position of the plane across the mesh</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ComparisonTable</name>
    <message>
        <source>Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min angle (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle &lt; 30° (% triangles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean quality Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hausdorff (% bbox diagonal)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sampling time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mesh building time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As thesis Table 4.2: entities counted without the box; Q is 1 for an equilateral triangle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smallest angle of each triangle, in % of the triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quality Q of each triangle (1: equilateral), in % of the triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smallest dihedral angle of each tetrahedron, in % of the tets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radius ratio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radius ratio 3r/R of each tetrahedron (1: regular, 0: flat), in % of the tets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remesh</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityController</name>
    <message>
        <source>Measuring complexity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The complexity analysis stopped without a result</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityDialog</name>
    <message>
        <source>Complexity Analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Analyse</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityPanel</name>
    <message>
        <source>%1 of %2 cells drawn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Geometric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size var. coeff.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of elements, box excluded (thesis Table 3.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sum of C_t + C_f + C_e + C_a over the elements (thesis Table 3.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standard deviation / mean of the volumes, areas and lengths (thesis Table 3.3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Q10</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Q50 (median)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Q90</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Var. coeff.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the &amp;heat map of elements per cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw cells with at &amp;least</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> elements</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells meeting fewer model elements are not drawn, so the model stays visible.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Global measures (thesis Tables 3.1–3.3): none yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elements per cell (thesis Table 3.4): none yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Global measures, box excluded (thesis Tables 3.1–3.3); geometric with h = %1 m, α = %2°.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elements per cell (thesis Table 3.4): none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Elements per cell (thesis Table 3.4), seed %1, %n Lloyd iteration(s); %2 cell(s) outside the model left out of the statistics.</source>
        <translation>
            <numerusform>Elements per cell (thesis Table 3.4), seed %1, %n Lloyd iteration; %2 cell(s) outside the model left out of the statistics.</numerusform>
            <numerusform>Elements per cell (thesis Table 3.4), seed %1, %n Lloyd iterations; %2 cell(s) outside the model left out of the statistics.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityWorkflow</name>
    <message>
        <source>&amp;Complexity…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measure the complexity of the model and show the elements per cell as a heat map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;ancel Complexity Analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the complexity analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export Complexity Cells…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the cells with their element counts as a VTK unstructured grid (.vtu)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Complexity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elements
per cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring the complexity of %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity measured with %1 cells in %2 s: %3 elements per cell at most, %4 on average</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity measured — see Complexity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity analysis failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity analysis failed — see Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity analysis cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Complexity Cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>VTK unstructured grid (*.vtu)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity cells exported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export the complexity cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity analysis cancelled: no result, the model is unchanged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no complexity analysis is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no complexity analysis yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::Core</name>
    <message>
        <source>two distinct points %1 apart at %2, closer than a volume mesher&apos;s merge tolerance (TetGen merges them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>triangle %1 of %2 and triangle %3 of %4 intersect near %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>region %1 has no boundary surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 lists the same side of surface %2 twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the boundary of the Universe is not closed: %1 edges are used an odd number of times</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the boundary of region %2 is not closed: %1 edges are used an odd number of times</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the sides of the Universe are inconsistent: %1 edges are not run as often one way as the other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the sides of region %2 are inconsistent: %1 edges are not run as often one way as the other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the sides of the Universe disagree with the surface normals: its volume is %1 (expected negative; region on the side the normal points to is &apos;+&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the sides of region %2 disagree with the surface normals: its volume is %1 (expected positive; region on the side the normal points to is &apos;+&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>side %1 of surface %2 is claimed by %3 regions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>side %1 of surface %2 belongs to no region nor to the Universe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of the %2 edges of %3 are on the border of surface %4 only: the model is not sealed there (it touches no other surface)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an edge of surface %1 has %2 triangles around it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>triangle %1 of %2 uses one vertex twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>triangle %1 of %2 has two corners at the same position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>triangle %1 of %2 has zero area (collinear corners)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>triangle %1 of %2 lies on the same three points as triangle %3 of %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>two triangles of surface %1 run their common edge the same way (flipped normals)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sliver shared by two surfaces: its shortest edge collapsed (Alg 4.4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>points closer than the resolution merged to undo intersecting triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output triangles still intersect after flips and vertex moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>valence-3 vertex of a tiny cell removed (Fig 4.8a)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>degenerate triangle on a free border removed (Fig 4.8b)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cap along a contact: vertex inserted into the contact (Alg 4.4, configuration 6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface entirely below the resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a connected part of the surface disappeared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the surface was split into more parts: this one is separate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>contact or border line not in the output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line of the output with no counterpart in the input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner not in the output (distance to the nearest output corner)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner of the output with no counterpart in the input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corners of one Voronoi cell joined by a line merged (Fig 4.6b)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a cell component with more than two points: points merged (Fig 4.6a)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a cell component with more than two points: its two closest merged (Fig 4.6a)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>model parts closer than d_resolution merged (Fig 4.7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>strip %1 (%2 m wide, limit %3 m) removed: its two lines merged half-way (Fig 4.7 per strip)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>strip %1 (%2 m wide, limit %3 m) removed: its two lines merged onto one of them (Fig 4.7 per strip)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>strip %1 (%2 m wide, limit %3 m) removed before remeshing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surfaces %1 and %2 fold over each other at %3: one space between them is on the side of %4 and of %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>region %1 is in more than one piece: a pocket of volume %2 between %3 at %4 is cut off from it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no file name given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write: it is a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot create a file in folder %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal error: file committed twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write: %1 (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the temporary file %1 vanished: %2 (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot replace the file: %1 (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cells export: array &apos;%1&apos; has %2 values for %3 cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot read the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs %2 bytes but only %3 are left at byte %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a Geogram file (first chunk is &apos;%1&apos;, expected &apos;HEAD&apos;) at byte %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>64-bit (GARGANTUA) Geogram files are not supported at byte %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a Geogram file (magic &apos;%1&apos;) at byte %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chunk &apos;%1&apos; claims %2 bytes but only %3 are left at byte %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chunk &apos;%1&apos; has %2 bytes more than its fields at byte %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute set &apos;%1&apos; is defined twice at byte %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; belongs to the undefined set &apos;%2&apos; at byte %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; of set &apos;%2&apos; is defined twice at byte %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; of %2 items × %3 bytes is larger than its chunk (%4 bytes left) at byte %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; should hold %2 bytes (%3 items of &apos;%4&apos;) but its chunk holds %5 at byte %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CMDL claims %1 strings in %2 bytes at byte %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; has elements of %2 bytes, expected %3 (%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot initialise zlib</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (after %2 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>decompresses to more than 4 GiB (a GeoFile indexes with 32 bits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Geogram attribute &apos;%1&apos; holds %2 bytes, not %3 items of its set &apos;%4&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; of &apos;%2&apos; is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; has dimension %2, expected %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; entry %2 is vertex %3, but the mesh has %4 vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; of item %2 is out of order or beyond the %3 corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not start at corner 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 items of &apos;%2&apos; need %3 corners, the file has %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>facet %1 has %2 corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;GEO::Mesh::cells::cell_type&apos; is not one char per cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 has geogram type %2 (only tets 0, prisms 2 and pyramids 3 are supported)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 has %2 corners, its type needs %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unexpected text outside a section: &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file does not start with $MeshFormat: not a Gmsh mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no $MeshFormat section: not a Gmsh mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected %1, found &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>section $%1 has no %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;version file-type data-size&quot; in $MeshFormat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MSH version %1 is not supported (use 4.1 or 2.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>binary MSH files are not supported: save as ASCII</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;dim tag \&quot;name\&quot;&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>$Entities in an MSH 2 file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;numPoints numCurves numSurfaces numVolumes&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>entity line too short (missing %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>negative number of physical tags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>negative number of bounding entities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;x y z&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 is defined twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;tag x y z&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;numEntityBlocks numNodes minNodeTag maxNodeTag&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;entityDim entityTag parametric numNodesInBlock&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the $Nodes header declares %1 nodes, its blocks hold %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>element type %1 (%2) is not supported: StrataMesh exchanges points, lines, triangles, tetrahedra, pyramids and prisms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a %1 needs %2 nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>element uses node %1, which is not in $Nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 uses node %2 twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;tag type numTags tags... nodes...&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>element line too short for its tags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;numEntityBlocks numElements minElementTag maxElementTag&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;entityDim entityTag elementType numElementsInBlock&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the $Elements header declares %1 elements, its blocks hold %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has %2 TFACEs but the Model3d header declares %3 for it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the key triangle of %1 is a triangle of several TFACEs of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot match %1 to a TFACE of %2: its key triangle is in no remaining TFACE and the TFACE at its position matches another one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>too few values, expected &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>list of ids of %1 is not ended by 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; in the list of %2 is not an integer id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends inside the list of ids of %1 (truncated file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends inside the key triangle of TFACE %1 (truncated file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TSURF &apos;%1&apos; is declared twice (first at line %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TFACE %1 is declared twice (first at line %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TFACE %1 names TSURF &apos;%2&apos;, which the header does not declare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TSurf &apos;%1&apos; is not declared by a TSURF line of the Model3d header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unnamed TSurf beyond the TSURFs declared by the Model3d header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>second TSurf object for TSURF &apos;%1&apos; (first at line %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TSURF &apos;%1&apos; has no TSurf object in the file (truncated file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>REGION &apos;%1&apos; names TFACE %2, which the header does not declare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>REGION id %1 is used twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no TSurf object in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 started at line %2 is not closed by &apos;}&apos; before %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends inside the HEADER block started at line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ZPOSITIVE must be Elevation or Depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coordinate system block started at line %1 has no END_ORIGINAL_COORDINATE_SYSTEM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends inside the coordinate system block started at line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends inside the { } block started at line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends before %1 closing the block started at line %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GOCAD line without an object type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends before the END of %1 (truncated file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing END of %1 before the next GOCAD object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Model3d object must come first in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>empty file: no GOCAD object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open the file (missing or not readable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex id %1 is already defined at line %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ATOM %1 refers to vertex %2, which is not defined before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRGL refers to vertex %1, which is not defined in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRGL uses the same vertex id twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 refers to vertex %2, which is not defined in %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no TFACE and no triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TFACE of %1 has no triangle (empty surface)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the model &apos;%1&apos; has no surface to write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has no triangle: Gocad cannot hold it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has a triangle using vertex %2 of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>region &apos;%1&apos; is bounded by surface %2 of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface %1 does not exist (the model has %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown mesh file extension &apos;%1&apos; (use %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown output extension &apos;%1&apos; (use %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a TSolid holds tetrahedra: the surface model &apos;%1&apos; has none (build a volume mesh first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown model file extension &apos;%1&apos; (expected %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open the file (missing or not a regular file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file holds no surface triangle (an empty model; volume cells alone give no surface)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal error: output planned after the commit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no file name given for the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the %1: it is a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 would replace the input file %2: choose another file, or ask to overwrite it (stratamesh-cli: --overwrite); nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>named twice: as the %1 and as the %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the %1: its folder %2 does not exist (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the %1: %2 is not a folder (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the %1 in folder %2: %3 (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal error: this output was not planned before the work</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal error: output written after the commit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the %1: %2 (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal error: outputs committed twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal error: the %1 was never written (nothing was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>entry missing from the archive (mesh_entities.txt lists %1 %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no such entity: mesh_entities.txt says &apos;Nb %1 %2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file ends before the %1 line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected %1 (a non-negative integer), found &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;Version&apos; without a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown .gm version %1 (versions 0, 1 and 2 are known)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only 3D GeoModels are supported (Dimension 3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;Nb&apos; line needs an entity type and a count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown mesh entity type &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nb %1 %2 is more than the file&apos;s %3 lines can describe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>second &apos;Nb %1&apos; line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 line has %2 fields, version %3 needs %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is beyond &apos;Nb %1 %3&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is defined twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a signed surface id like +3 or -3, found &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has %2 %3 as boundary, but &apos;Nb %2&apos; is %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;Nb %1 %2&apos; but %1 %3 is never described</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the GeoModel has no surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Universe has surface %1 as boundary, beyond &apos;Nb Surface&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>geological entity line needs a type, an id, a name and a feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 &apos;%2&apos; has %3 %4 as child, but mesh_entities.txt has %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a corner has one vertex, this one has %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a line is a chain of edges, this one has %1 vertices and %2 edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface without facets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>compareRingMeshTopology needs the recovered topology (recoverTopology)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a line without vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has no triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 has no region: a GeoModel stores cells per region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bad element count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>element %1 declares %2 items, more than the file of %3 bytes can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenMesh could not read this file as a surface mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>non-manifold faces: %1 vertices in the file, %2 after reading (save as ASCII PLY, which keeps them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 face(s) could not be added (degenerate or non-manifold faces)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;element NAME COUNT&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>property before any element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;property TYPE NAME&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line too short for the properties of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line too short for its list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face uses vertex %1 of %2 (numbered from 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertices without x, y and z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a face needs three vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a PLY file: the first line is not &quot;ply&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown PLY format &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PLY header has no end_header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PLY header has no format line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no triangle in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an ASCII STL file starts with &quot;solid&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;%1&quot;, found &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>text after endsolid: &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;facet&quot; or &quot;endsolid&quot;, found &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>facet %1 has more than three vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;endloop&quot;, found &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>facet %1 has two equal corners (degenerate facet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends before endsolid (truncated file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>binary STL of %1 bytes, its header announces %2 facets (%3 bytes): truncated or not an STL file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>neither an ASCII STL (starting with &quot;solid&quot;) nor a binary STL (84 bytes or more)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a vertex needs three coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coordinate &apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face vertex &apos;%1&apos; is not an index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face uses vertex %1 (numbered from 1, or back from -1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a face needs at least three vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face uses vertex %1, the file defines %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>empty file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an OFF file: the first word is not OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only 3D OFF files are supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>binary OFF files are not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends before the vertex and face counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected the vertex and face counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid vertex and face counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends after %1 of %2 vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file ends after %1 of %2 faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a face of %1 vertices lists %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face vertex &apos;%1&apos; is not an index from 0 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an OBJ or OFF file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the face uses vertex %1 twice (a degenerate face)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>non-manifold faces: this face shares an edge with two other faces, or runs along it the same way as its neighbour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; is not manifold at triangle %2: OpenMesh cannot store it as STL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenMesh could not write the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown surface mesh extension &apos;%1&apos; (use .obj, .off, .stl or .ply)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an %1 file holds one surface and the model &apos;%2&apos; has %3: choose one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has a non-finite coordinate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface &apos;%1&apos;: triangle %2 uses vertex %3 of %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unexpected end of file (expected %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is negative (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2, more than the remaining %3 bytes of the file can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a Gocad file (expected &quot;GOCAD TSolid 1&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a TSolid object, found &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>empty file: not a Gocad TSolid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HEADER without &apos;{&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HEADER block not closed by &apos;}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>block not closed by &apos;}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs an id and three coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex id %1 is used twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs an id and the id of the vertex it shares</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 refers to vertex %3, which is not defined before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex %1 is not defined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TETRA needs four vertex ids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TETRA uses the same vertex twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRGL outside a MODEL TFACE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRGL needs three vertex ids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRGL uses the same vertex twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a TSolid needs tetrahedra: the mesh &apos;%1&apos; has no cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a TSolid holds tetrahedra only: the mesh &apos;%1&apos; has %2 prisms and %3 pyramids (use .vtu or .msh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, more than the file of %3 bytes can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, the file ends after %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, &quot;%3&quot; comes after %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, the line holds more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 strings, more than the file of %3 bytes can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 strings, the file ends after %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 data is cut short in string %2 of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is followed by &apos;%2&apos; on its line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file ends before %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a count, found &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares a negative count %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has type &apos;%2&apos;, which is not a legacy VTK data type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has type &apos;%2&apos;: it must hold numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a legacy VTK file: the first line is not &quot;# vtk DataFile Version x.y&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file version &apos;%1&apos; is not x.y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file version %1.%2 is newer than the 5.1 StrataMesh reads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file ends before its title line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected ASCII or BINARY after the title, found &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected DATASET after %1, found &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DATASET %1 is not read by StrataMesh (UNSTRUCTURED_GRID or POLYDATA only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a second %1 (the first is at line %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>found &quot;%1&quot; where a keyword belongs: the section before it holds more values than it declares</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>POINTS has type &apos;bit&apos;: it must hold coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>POINTS declares %1 points, more than the file of %2 bytes can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of a version 5 file goes on with &quot;%2 vtktypeint64&quot; (or vtktypeint32), found &quot;%3&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 has type &apos;%3&apos; (vtktypeint64 or vtktypeint32 expected)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 cells in %3 values: a cell takes one at least</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, cell %3 (numbered from 0) runs past them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, its %3 cells use %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares no offsets but %2 connectivity values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 OFFSETS and CONNECTIVITY have different types</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 OFFSETS start at %2, not 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 OFFSETS decrease at cell %2 (numbered from 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 OFFSETS end at %2, %3 connectivity values are declared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the data set has no POINTS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CELLS has no CELL_TYPES to go with it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CELL_TYPES has no CELLS to go with it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CELL_TYPES declares %1 values, CELLS at line %2 declares %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 comes after the data of the cells or points: the geometry goes first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 x %3 values, more than the file can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has dimension &apos;%2&apos; (1, 2 or 3 expected)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has &apos;%2&apos; components (a number from 1 expected)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 goes on with &quot;LOOKUP_TABLE default&quot;, found &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds %2, not a colour from 0 to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 colours, more than the file of %3 bytes can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 components (from 1 to 1048576)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 x %3 values, more than the file of %4 bytes can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 field data holds %2, not a byte of text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>VTK cannot read it: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 has %2 %3 (expected a whole number from 0 to 2147483647)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown VTK extension &apos;%1&apos; (use .vtu, .vtp or .vtk)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no triangle and no volume cell in the file (empty model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the RegionSides field data names surface %1, which the file does not have</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the RegionSides field data does not match the regions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a .vtp file holds surfaces only: the mesh &apos;%1&apos; has %2 volume cells (use .vtu or .vtk)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the header of a compressed array is damaged or too large: %1 blocks of %2 bytes, the last of %3, in a file of %4 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a compressed array states no block but holds data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the header of a compressed array is cut short</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>block %1 of a compressed array states %2 compressed bytes, more than the file of %3 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2, more than the file of %3 bytes can hold even compressed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a DataArray has type &quot;%1&quot;, which is not a VTK type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a readable zip archive (missing file, or no zip central directory)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corrupt zip directory after %1 entries: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>entry missing from the archive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>entry cannot be located in the archive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open the entry: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot decompress the entry after %1 bytes: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>entry larger than %1 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot create the zip archive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot add the entry to the zip archive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write the entry (disk full?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot finish the entry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot finish the zip archive (disk full?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>region %1 lists surface %2 which does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no point strictly inside region %1 was found (is its boundary closed and consistently oriented?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the model has no surface to tetrahedralise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface %1: triangle %2 has two corners at the same point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot create a work folder: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen parameters must be finite and not negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a Gocad file: expected &apos;GOCAD &lt;type&gt;&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &apos;GOCAD &lt;type&gt;&apos; to start the next object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is not finite (non-finite vertex)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is beyond the bound of 1e15 that keeps squared distances and volumes finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coordinate %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point %1 (numbered from 0): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%2 %1 is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%2 %1 is not finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%2 %1 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%2 %1 is not an integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x coordinate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y coordinate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z coordinate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TFACE id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>BSTONE vertex id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>BORDER id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>BORDER corner vertex id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>BORDER next vertex id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>referenced vertex id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRGL vertex id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot replace the file: %1 (no output was written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an entity count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an entity id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a boundary id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a geological entity id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a child id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex %1 (numbered from 0): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex %1 (numbered from 0, as faces index it): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>facet %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coordinate &apos;%1&apos; %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 (numbered from 0, VTK type %2) has %3 point ids, its type needs %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 (numbered from 0, VTK type %2) has %3 point ids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 has VTK type %2, which StrataMesh does not exchange (tets, pyramids, wedges, triangles, lines and vertices only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell %1 uses point %2 of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is not a whole number from 0 to 18446744073709551615</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is not an integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is out of range for %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 data is cut short: %2 bits, %3 bytes are left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 data is cut short: %2 values of %3 bytes, %4 bytes are left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 value &apos;%2&apos; %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is out of range for a 4-byte integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a keyword of %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, the cell section is missing: the file has no cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, the cell section at line %3 declares %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 declares %2 values, POINTS at line %3 declares %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ExaggerationWorkflow</name>
    <message>
        <source>Vertical E&amp;xaggeration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stretch the vertical axis of both views, to see thin layers and low dips</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (true scale)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical exaggeration %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical exaggeration off: true scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical exaggeration %1: the views are not to scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical Exaggeration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical axis stretched by (%1 to %2):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Other…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Other (%1)…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ExportController</name>
    <message>
        <source>Exporting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The export stopped without a result</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ExportDialog</name>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (*%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>4.1 (Gmsh 4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2.2 (older readers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep elements without a group (Gmsh Mesh.SaveAll)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gmsh keeps only elements of a physical group; this writes the others too, in an entity without one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MSH &amp;version:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Surface:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F&amp;ile:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This format holds tetrahedra; a surface model has none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This format holds no volume cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This format holds tetrahedra only; this mesh has pyramids and prisms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every surface but the chosen one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>surface names</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feature types (horizon, fault…)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>regions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>contact lines and corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>volume cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pyramids and prisms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>double precision (coordinates stored as 32-bit floats)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 does not keep: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing can be exported yet: open a model first.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ExportWorkflow</name>
    <message>
        <source>&amp;Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the model, its remesh or a volume mesh to another file format</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No model is open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshed model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No remeshed model: run Mesh &gt; Remesh… first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No TetGen mesh: run Mesh &gt; Tetrahedralise… first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The last tetrahedralisation did not mesh the remeshed model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen mesh of the input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen failed on the input model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen mesh of the remesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen failed on the remeshed model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No hybrid mesh: run Mesh &gt; Hybrid Mesh… first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot tell the format from the extension (use %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another run is under way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported as %1 in %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 elements without a region, surface or line were left out, as Gmsh does; “Keep elements without a group” keeps them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::FeatureLegend</name>
    <message>
        <source>Horizons</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unconformities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n surface(s))</source>
        <translation>
            <numerusform>%1 (%n surface)</numerusform>
            <numerusform>%1 (%n surfaces)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (hidden)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Legend</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::HistogramChart</name>
    <message>
        <source>Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln triangle(s), %2 %</source>
        <translation>
            <numerusform>%1: %Ln triangle, %2 %</numerusform>
            <numerusform>%1: %Ln triangles, %2 %</numerusform>
        </translation>
    </message>
    <message>
        <source>[%1, %2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridController</name>
    <message>
        <source>Building the hybrid mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The hybrid mesher stopped without a result</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridDialog</name>
    <message>
        <source>Hybrid Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Build Mesh</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridPanel</name>
    <message>
        <source>C&amp;olour cells by:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cell type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pyramids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prisms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max dihedral (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slivers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedra with a dihedral angle below 5° or above 175°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Valid mixed mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not valid: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invalid cells found: %1  ·  repaired: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No hybrid cell could be kept: this is TetGen&apos;s mesh of the remesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time: %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean min dihedral (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean over the cells of each cell&apos;s smallest dihedral angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells between two surfaces: %1  ·  at Voronoi vertices: %2  ·  transition pyramids: %3  ·  TetGen&apos;s tets: %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridWorkflow</name>
    <message>
        <source>&amp;Hybrid Mesh…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mesh the regions with prisms in the thin layers, tetrahedra elsewhere and pyramids between them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel &amp;Hybrid Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the hybrid mesher; the previous hybrid mesh is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save &amp;Hybrid Mesh As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the hybrid mesh as a VTK (.vtu) or Gmsh (.msh) file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Hybrid Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral
angle (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tetrahedron</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pyramid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>prism</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cell type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Building the hybrid mesh of %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid mesh: %1 tetrahedra, %2 pyramids, %3 prisms, %4 in %5 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not valid (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid mesh built — see Hybrid Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The hybrid mesh is not valid — see Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid meshing failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid meshing failed — see Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid meshing cancelled; the previous mesh is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid meshing cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid mesh: %1 cells, %2 sites</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>VTK unstructured grid (*.vtu)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gmsh mesh (*.msh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Hybrid Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a hybrid mesh is saved as a .vtu or .msh file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid mesh saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save the hybrid mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid meshing cancelled: no mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no hybrid mesh is being built</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no hybrid mesh yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::LedgerPanel</name>
    <message>
        <source>No simplification</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All kinds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only the records whose text holds this (any column)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::LedgerTableModel</name>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input entities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner merge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multi-point merge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close feature merge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degenerate contact triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degenerate border triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Valence-3 vertex removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface created</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line created</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner created</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unresolved intersection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (distance)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (area)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (length)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface part lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface part created</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show &amp;Box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the surfaces of the model&apos;s bounding box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show Triangle &amp;Edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw the edges of every surface triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Look at the whole model from the south-west</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About StrataMesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n surface(s)</source>
        <translation>
            <numerusform>%n surface</numerusform>
            <numerusform>%n surfaces</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n line(s)</source>
        <translation>
            <numerusform>%n line</numerusform>
            <numerusform>%n lines</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s)</source>
        <translation>
            <numerusform>%n corner</numerusform>
            <numerusform>%n corners</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n region(s)</source>
        <translation>
            <numerusform>%n region</numerusform>
            <numerusform>%n regions</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (box excluded)  ·  %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With the box: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Analyse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>StrataMesh[*]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1[*] — StrataMesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)[*] — StrataMesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Link Cameras</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the input and output views together; unchecked, each view has its own camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to redo</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::MessagePanel</name>
    <message>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Info</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Severity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Location</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
Click to show it in the views</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ModelTreeModel</name>
    <message>
        <source>horizon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unconformity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surfaces (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Horizons (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faults (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unconformities (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other Surfaces (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Box (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Surface %1 — %2 %3, %n triangle(s)</source>
        <translation>
            <numerusform>Surface %1 — %2 %3, %n triangle</numerusform>
            <numerusform>Surface %1 — %2 %3, %n triangles</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Line %1 — length %2, %n surface(s)</source>
        <translation>
            <numerusform>Line %1 — length %2, %n surface</numerusform>
            <numerusform>Line %1 — length %2, %n surfaces</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Corner %1 at (%2, %3, %4) — %n line(s)</source>
        <translation>
            <numerusform>Corner %1 at (%2, %3, %4) — %n line</numerusform>
            <numerusform>Corner %1 at (%2, %3, %4) — %n lines</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Region %1 — %n boundary surface(s)</source>
        <translation>
            <numerusform>Region %1 — %n boundary surface</numerusform>
            <numerusform>Region %1 — %n boundary surfaces</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stratamesh::ModelTreePanel</name>
    <message>
        <source>Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter by name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the surfaces of the model&apos;s bounding box</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ModelTreeWorkflow</name>
    <message>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model &amp;Tree</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n surface(s)</source>
        <translation>
            <numerusform>%n surface</numerusform>
            <numerusform>%n surfaces</numerusform>
        </translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output surface %1, triangle %2: min angle %3°, Q = %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface %1, triangle %2: min angle %3°, Q = %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::OpenModelController</name>
    <message>
        <source>Building the sample model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recovering lines and corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checking validity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading stopped without a result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sample model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Structural models</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::OpenWorkflow</name>
    <message>
        <source>&amp;Open Model…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a structural model file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Sample Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the synthetic model bundled with StrataMesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 opened in %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No validity problem found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n validity problem(s) — see Messages</source>
        <translation>
            <numerusform>%n validity problem — see Messages</numerusform>
            <numerusform>%n validity problems — see Messages</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not open the model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ParamForm</name>
    <message>
        <source>(thesis %1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::Params</name>
    <message>
        <source>Characteristic size &amp;h:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elements smaller than h (h² for surfaces, h³ for regions) are complex.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Angle α:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angles between elements smaller than α are complex.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of &amp;cells:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells of the volumetric Voronoi diagram in which model elements are counted (the thesis uses 100, 1000 and 10000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ra&amp;ndom seed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed of the initial random sites: the same seed gives the same cells.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Lloyd iterations:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lloyd iterations of the volumetric centroidal Voronoi tessellation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Iterations:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Iterations of the centroidal Voronoi optimisation of the sites.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boundary &amp;weight α:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Weight of the boundary energy in F = (1 − α) F_CVT + α F_B.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Lloyd iterations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lloyd iterations instead of L-BFGS (the CVT energy alone: no boundary weight).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of &amp;sites:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sites spread over all the surfaces; each becomes about one vertex. At least one per surface; 0: from the edge length.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target &amp;edge length:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The number of sites is derived from the total area for this edge length (hexagonal packing); 0: from the number of sites.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;d_resolution:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>× edge length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove thin s&amp;trips under:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surfaces narrower than this between two long lines (a small fault throw) are removed whole before remeshing, their two lines merged into one; 0 keeps them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed of the initial random sampling: the same seed gives the same mesh.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;finement rounds:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rounds of more sites where the result is not valid or its topology differs from the input&apos;s (4 more while it is not valid); 0 turns refinement off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Adaptive density (more sites near corners)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Site density grows near corners, so small features keep more triangles.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Merge all extra points of a cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A cell part with more than two points has them all merged, as in the thesis; without it, only the closest until two are left, which keeps more of the model.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quality (radius-edge ratio):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest circumradius to shortest edge ratio TetGen accepts (its q switch); 0 turns quality refinement off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Maximum tet volume:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest volume of a tetrahedron (TetGen&apos;s a switch); 0 sets none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Time limit per model:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen is stopped after this time on each model; a raw input model can keep it busy for hours. 0 sets none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Memory &amp;limit per model:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address space the TetGen helper may use; 0 sets none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Let TetGen &amp;refine the surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Without it every surface triangle is kept as it is (TetGen&apos;s Y switch), so the meshes show what the surfaces themselves give.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keep nearly coplanar triangles apart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When TetGen refines the surfaces it merges nearly coplanar triangles, which moves region volumes by about 1e-6; this keeps them exact (its M switch) but refines much more.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of volume &amp;sites:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sites of the volumetric centroidal Voronoi diagram of the model&apos;s box; the surfaces are remeshed from them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Thin-layer ratio:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A cell between two surface triangles becomes a prism or a pyramid when its height is below this ratio times its triangles&apos; size.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Volume CVT &amp;iterations:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lloyd iterations of the volumetric centroidal Voronoi diagram.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest quad &amp;warp:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle between the two halves of a prism&apos;s or pyramid&apos;s quad face above which the cell is left to the tets.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sur&amp;face site iterations:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lloyd steps moving the sites whose cell meets a surface to the centroid of their restricted cell; 0 turns them off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Transition &amp;pyramid height:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apex height of a pyramid on a quad face that meets the tets, over the square root of the quad&apos;s area.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>× feature distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells near c&amp;lose features:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Near two features that do not meet (the two lines of a small fault throw, close corners), cells are at most this times their distance, so that both are kept without needles; the sites grow accordingly, to at most 4 times those asked. Use it with the strip factor at 0 to keep small throws rather than remove them; 0 turns it off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pin sites on close features</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Vertex-dual tets, smallest angle:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where four Voronoi cells meet, the tet of their sites, or of their points on the surfaces when the cells are cut, is kept when it and its neighbours have no dihedral angle below this; 180 leaves the whole volume to TetGen&apos;s tets.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leave &amp;cut Voronoi vertices to TetGen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where the four Voronoi cells of a vertex meet a surface, TetGen&apos;s tets fill the place instead of the tet linking their points on the surfaces and their sites (Fig. 5.4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Features smaller than this may be simplified: parts closer than it are merged, thin strips narrower than it and the strip factor are removed; 0 simplifies nothing and pins sites on close features. -1 (Auto): nothing merged, thin strips removed by the strip factor alone. At most a tenth of the bounding-box diagonal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refinement rounds put sites on the corners and lines around each topology change, as close as the nearest other feature, and grade the surfaces around them: more features are kept, with up to 4 times the sites asked plus the sites pinned on the features (9 times in all on an 8-fault network at 1000 sites), and more triangles under 30°. Always on when d_resolution is 0.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ProjectWorkflow</name>
    <message>
        <source>edge %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 sites</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>, %n iteration(s)</source>
        <translation>
            <numerusform>, %n iteration</numerusform>
            <numerusform>, %n iterations</numerusform>
        </translation>
    </message>
    <message>
        <source>, d_resolution %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, adaptive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locate the Input Model %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Project…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a StrataMesh project: its model, remesh runs and reviews</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the remesh runs, their results and reviews as a project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the project under another name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R&amp;uns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project&apos;s runs and reviews have not been saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show Run %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Showing run %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>StrataMesh projects (*.smproj)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open the project %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project&apos;s input model is not where the project says: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project not opened: its input model %1 is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open the project&apos;s input model — see Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1: its review was not read (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Project %1 opened: %n run(s), read from its folder without remeshing</source>
        <translation>
            <numerusform>Project %1 opened: %n run, read from its folder without remeshing</numerusform>
            <numerusform>Project %1 opened: %n runs, read from its folder without remeshing</numerusform>
        </translation>
    </message>
    <message>
        <source>The input model was found at %1: save the project to keep it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened project %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save the project</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Project saved with %n run(s)</source>
        <translation>
            <numerusform>Project saved with %n run</numerusform>
            <numerusform>Project saved with %n runs</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare Runs %1 and %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show Input vs Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comparing run %1 with run %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1: %2 sites, %3 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::RecentFiles</name>
    <message>
        <source>&amp;%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File not found: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forget the files opened before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no file opened yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::RemeshController</name>
    <message>
        <source>Remeshing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshing stopped without a result</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::RemeshDialog</name>
    <message>
        <source>Remesh Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remesh</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::RemeshWorkflow</name>
    <message>
        <source>&amp;Remesh…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remesh all the surfaces at a chosen resolution, keeping the model conformal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Cancel Remeshing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the remeshing; the input model is left as it is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Remeshed Model &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the remeshed model as a Gocad, RINGMesh, Gmsh or VTK file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshing %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Remeshed with %1 sites in %2 s: %3 triangles, %n simplification(s) recorded</source>
        <translation>
            <numerusform>Remeshed with %1 sites in %2 s: %3 triangles, %n simplification recorded</numerusform>
            <numerusform>Remeshed with %1 sites in %2 s: %3 triangles, %n simplifications recorded</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The remeshed model is NOT valid: %n problem(s) left after local refinement; saving it is at your own risk</source>
        <translation>
            <numerusform>The remeshed model is NOT valid: %n problem left after local refinement; saving it is at your own risk</numerusform>
            <numerusform>The remeshed model is NOT valid: %n problems left after local refinement; saving it is at your own risk</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remeshed, NOT valid: %n problem(s) — see Messages</source>
        <translation>
            <numerusform>Remeshed, NOT valid: %n problem — see Messages</numerusform>
            <numerusform>Remeshed, NOT valid: %n problems — see Messages</numerusform>
        </translation>
    </message>
    <message>
        <source>Remeshing failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshing failed — see Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshing cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output: %1 sites, %2 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Remeshed Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshed model saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save the remeshed model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remeshing cancelled: the previous result, if any, is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The remeshed model has not been saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Re&amp;view as CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Review as CSV: every record with its decision and note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write every simplification with its decision and note as a CSV table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Review</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Review</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Remeshed: %n simplification(s) — see Review</source>
        <translation>
            <numerusform>Remeshed: %n simplification — see Review</numerusform>
            <numerusform>Remeshed: %n simplifications — see Review</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Review</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Review exported: %1 of %2 records reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export the review</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no remeshed model yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no remesh is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>… (%n in all)</source>
        <translation>
            <numerusform>… (%n in all)</numerusform>
            <numerusform>… (%n in all)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n topology change(s) left where refinement stopped (%1 of %2 rounds, %3 sites), involving %4 — see Review</source>
        <translation>
            <numerusform>%n topology change left where refinement stopped (%1 of %2 rounds, %3 sites), involving %4 — see Review</numerusform>
            <numerusform>%n topology changes left where refinement stopped (%1 of %2 rounds, %3 sites), involving %4 — see Review</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n topology change(s), involving %1 — see Review</source>
        <translation>
            <numerusform>%n topology change, involving %1 — see Review</numerusform>
            <numerusform>%n topology changes, involving %1 — see Review</numerusform>
        </translation>
    </message>
    <message>
        <source>Quality</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quality</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ReviewPanel</name>
    <message>
        <source>&amp;Accept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accept the selected simplification (A; again to reopen it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Flag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flag the selected simplification for a closer look (F; again to reopen it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write a note on the selected simplification (N; Enter keeps it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Previous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go to the previous record and show it in both views (K or Up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ne&amp;xt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go to the next record and show it in both views (J or Down)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 reviewed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ReviewTableModel</name>
    <message>
        <source>Accepted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flagged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decision</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Review note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>#</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::RunsPanel</name>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sites</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hausdorff (% diag.)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show one run in the input view and another in the output view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input vs Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the input model again beside the run shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare Runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input view:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output view:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ScriptRunner</name>
    <message>
        <source>it could not start (no model shown, or another run is going on)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this colouring is not available now (the distance needs a remesh before)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it was cancelled or failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step %1 (%2) failed: %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::StepsWorkflow</name>
    <message>
        <source>Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;teps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show Problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the Messages, where each validity problem of the model is listed; a click on one flies the views to it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complexity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Volume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a model (File &gt; Open Model…).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no validity problem found.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %n validity problem(s) — see Messages.</source>
        <translation>
            <numerusform>%1: %n validity problem — see Messages.</numerusform>
            <numerusform>%1: %n validity problems — see Messages.</numerusform>
        </translation>
    </message>
    <message>
        <source>Measured with %1 Voronoi cells.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elements per Voronoi cell as a heat map (ch. 3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 sites: %2 vertices, %3 triangles, %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All surfaces at once at a chosen resolution (ch. 4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen meshes made.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hybrid mesh of %1 cells.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen meshes of input and remesh, or a hybrid mesh (ch. 5).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The input, the remesh or a volume mesh in another format.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::StudyWindow</name>
    <message>
        <source>Task</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sites asked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean triangle quality Q against the resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output triangles against the resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Task %1 — %2: input (left), remesh (right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open the task</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Study %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter the rows (model, status, error…)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quality</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Element counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n task(s), %1 ok; double-click a row to see its input and output</source>
        <translation>
            <numerusform>%n task, %1 ok; double-click a row to see its input and output</numerusform>
            <numerusform>%n tasks, %1 ok; double-click a row to see its input and output</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stratamesh::StudyWorkflow</name>
    <message>
        <source>Open S&amp;tudy…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the table of a study run by stratamesh-cli study (.smstudy or study.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>StrataMesh studies (*.smstudy);;Gathered study tables (study.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open the study</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshController</name>
    <message>
        <source>Tetrahedralising the input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralisation stopped without a result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralising the input and the remesh</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshDialog</name>
    <message>
        <source>Input and &amp;remesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Input only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Models</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remesh the model first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tetrahedralise</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshPanel</name>
    <message>
        <source>ok</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>timed out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>killed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen was not run on the input: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen was not run on the remesh: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen failed on the input after %1 s: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen failed on the remesh after %1 s: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;olour tets by:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slivers (min dihedral &lt; 5°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen time (s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshWorkflow</name>
    <message>
        <source>&amp;Tetrahedralise…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mesh the regions of the input and of the remesh with TetGen and compare the tetrahedra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel &amp;Tetrahedralisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop TetGen; nothing is kept of this run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tetrahedra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min dihedral
angle (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralising %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input: %1 tets, %2 slivers, min dihedral %3° in %4 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remesh: %1 tets, %2 slivers, min dihedral %3° in %4 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen failed on a model — see Tetrahedra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralisation failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralisation failed — see Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralisation cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralisation cancelled: the previous meshes, if any, are kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TetGen is not running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tetrahedralised — see Tetrahedra and Quality</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::ViewWorkflow</name>
    <message>
        <source>&amp;Colour By</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Entity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Triangle &amp;Min Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Triangle &amp;Quality Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Distance to the Other Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour each vertex by its distance to the other model (needs a remesh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reverse Colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Swap the ends of the colour map (bad is yellow by default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;lip Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clip Both Views</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cut the surfaces and the tet meshes of both views with one plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Across &amp;X (east)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Across &amp;Y (north)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Across &amp;Z (up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position of the clip plane across the models</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next &amp;Worst Triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fly to the triangles of the output (or the input) by increasing quality Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour by %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reverse Colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unreverse Colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min angle (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distance
(model units)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 triangles highlighted for a bar of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>min angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n triangle(s) of the output highlighted: %1 in [%2, %3]</source>
        <translation>
            <numerusform>%n triangle of the output highlighted: %1 in [%2, %3]</numerusform>
            <numerusform>%n triangles of the output highlighted: %1 in [%2, %3]</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n triangle(s) of the input highlighted: %1 in [%2, %3]</source>
        <translation>
            <numerusform>%n triangle of the input highlighted: %1 in [%2, %3]</numerusform>
            <numerusform>%n triangles of the input highlighted: %1 in [%2, %3]</numerusform>
        </translation>
    </message>
    <message>
        <source>Worst triangle %1 of the output: surface %2, triangle %3, Q = %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Worst triangle %1 of the input: surface %2, triangle %3, Q = %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clip Both Views</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the Clip Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the Clip Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear &amp;Highlight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the highlight of a histogram bar&apos;s triangles or of the worst triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no remeshed model yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::Workbench</name>
    <message>
        <source>Unsaved Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 Save it before it is replaced?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 Save them before they are replaced?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stratamesh::Workflow</name>
    <message>
        <source>Cancelling…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
