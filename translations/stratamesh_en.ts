<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
    <message>
        <source>Remeshing and meshing of 3D structural models: conformal surface remeshing with restricted Voronoi diagrams, complexity measures and hybrid volume meshes, after J. Pellerin&apos;s PhD thesis.</source>
        <translation type="unfinished"></translation>
    </message>
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
</context>
<context>
    <name>GuiOptions</name>
    <message>
        <source>StrataMesh: remeshing and meshing of 3D structural models.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the model in &lt;file&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load the model, save the window as a PNG image in &lt;png&gt; and exit (status 0 when saved, 1 when the image could not be written, 2 when the model could not be opened).</source>
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
    <message>
        <source>StrataMesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — StrataMesh</source>
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
        <source>%1 opened in %2 s</source>
        <translation type="unfinished"></translation>
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
        <source>Structural models (*.ml *.ts *.obj *.off);;Gocad Model3d (*.ml);;Gocad TSurf (*.ts);;Wavefront OBJ (*.obj);;Object File Format (*.off);;All files (*)</source>
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
</context>
</TS>
