<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
    <message>
        <source>Remeshing and meshing of 3D structural models: conformal surface remeshing with restricted Voronoi diagrams, complexity measures and hybrid volume meshes, after J. Pellerin&apos;s PhD thesis.</source>
        <translation>Remaillage et maillage de modèles structuraux 3D : remaillage conforme des surfaces par diagrammes de Voronoï restreints, mesures de complexité et maillages volumiques hybrides, d&apos;après la thèse de doctorat de J. Pellerin.</translation>
    </message>
    <message>
        <source>StrataMesh is free software: you can redistribute it and/or modify it under the terms of the GNU Affero General Public License, version 3 or (at your option) any later version (AGPL-3.0-or-later). It comes with no warranty.</source>
        <translation>StrataMesh est un logiciel libre : vous pouvez le redistribuer et/ou le modifier selon les termes de la licence publique générale GNU Affero, version 3 ou (à votre choix) toute version ultérieure (AGPL-3.0-or-later). Il est fourni sans aucune garantie.</translation>
    </message>
    <message>
        <source>Tetrahedral comparison meshes are made by TetGen 1.5 (Hang Si, WIAS Berlin), used under the AGPL-3.0; TetGen runs in a separate process.</source>
        <translation>Les maillages tétraédriques de comparaison sont produits par TetGen 1.5 (Hang Si, WIAS Berlin), utilisé sous licence AGPL-3.0 ; TetGen s&apos;exécute dans un processus séparé.</translation>
    </message>
    <message>
        <source>Built with Qt, VTK, CGAL, Eigen, OpenMesh, oneTBB, nanoflann and LBFGSpp.</source>
        <translation>Construit avec Qt, VTK, CGAL, Eigen, OpenMesh, oneTBB, nanoflann et LBFGSpp.</translation>
    </message>
    <message>
        <source>About StrataMesh</source>
        <translation>À propos de StrataMesh</translation>
    </message>
</context>
<context>
    <name>GuiOptions</name>
    <message>
        <source>StrataMesh: remeshing and meshing of 3D structural models.</source>
        <translation>StrataMesh : remaillage et maillage de modèles structuraux 3D.</translation>
    </message>
    <message>
        <source>Open the model in &lt;file&gt;.</source>
        <translation>Ouvrir le modèle contenu dans &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Load the model, save the window as a PNG image in &lt;png&gt; and exit (status 0 when saved, 1 when the image could not be written, 2 when the model could not be opened).</source>
        <translation>Charger le modèle, enregistrer la fenêtre en image PNG dans &lt;png&gt; et quitter (code 0 si l&apos;image est enregistrée, 1 si elle n&apos;a pas pu être écrite, 2 si le modèle n&apos;a pas pu être ouvert).</translation>
    </message>
    <message>
        <source>User interface language: fr or en.</source>
        <translation>Langue de l&apos;interface : fr ou en.</translation>
    </message>
    <message>
        <source>Start with the box surfaces shown.</source>
        <translation>Démarrer avec les surfaces de la boîte affichées.</translation>
    </message>
    <message>
        <source>Start with triangle edges shown.</source>
        <translation>Démarrer avec les arêtes des triangles affichées.</translation>
    </message>
    <message>
        <source>Model to open (same as --open).</source>
        <translation>Modèle à ouvrir (comme --open).</translation>
    </message>
    <message>
        <source>Unknown language &apos;%1&apos;: use fr or en.</source>
        <translation>Langue « %1 » inconnue : utilisez fr ou en.</translation>
    </message>
</context>
<context>
    <name>ValidityMessages</name>
    <message>
        <source>… and %1 more problems of kind “%2”</source>
        <translation>… et %1 autres problèmes de type « %2 »</translation>
    </message>
    <message>
        <source>The model is not valid</source>
        <translation>Le modèle n&apos;est pas valide</translation>
    </message>
</context>
<context>
    <name>stratamesh::FeatureLegend</name>
    <message>
        <source>Horizons</source>
        <translation>Horizons</translation>
    </message>
    <message>
        <source>Faults</source>
        <translation>Failles</translation>
    </message>
    <message>
        <source>Unconformities</source>
        <translation>Discordances</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Boîte</translation>
    </message>
    <message>
        <source>Other surfaces</source>
        <translation>Autres surfaces</translation>
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
        <translation>%1 (masquée)</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(sans nom)</translation>
    </message>
    <message>
        <source>Legend</source>
        <translation>Légende</translation>
    </message>
</context>
<context>
    <name>stratamesh::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>&amp;Open Model…</source>
        <translation>&amp;Ouvrir un modèle…</translation>
    </message>
    <message>
        <source>Open a structural model file</source>
        <translation>Ouvrir un fichier de modèle structural</translation>
    </message>
    <message>
        <source>Open &amp;Sample Model</source>
        <translation>Ouvrir le modèle d&apos;&amp;exemple</translation>
    </message>
    <message>
        <source>Show the synthetic model bundled with StrataMesh</source>
        <translation>Afficher le modèle synthétique fourni avec StrataMesh</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>Show &amp;Box</source>
        <translation>Afficher la &amp;boîte</translation>
    </message>
    <message>
        <source>Show the surfaces of the model&apos;s bounding box</source>
        <translation>Afficher les surfaces de la boîte englobante du modèle</translation>
    </message>
    <message>
        <source>Show Triangle &amp;Edges</source>
        <translation>Afficher les &amp;arêtes des triangles</translation>
    </message>
    <message>
        <source>Draw the edges of every surface triangle</source>
        <translation>Dessiner les arêtes de chaque triangle des surfaces</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Réinitialiser la caméra</translation>
    </message>
    <message>
        <source>Look at the whole model from the south-west</source>
        <translation>Voir tout le modèle depuis le sud-ouest</translation>
    </message>
    <message>
        <source>&amp;About StrataMesh</source>
        <translation>À &amp;propos de StrataMesh</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>À propos de &amp;Qt</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <source>&amp;Messages</source>
        <translation>&amp;Messages</translation>
    </message>
    <message>
        <source>StrataMesh</source>
        <translation>StrataMesh</translation>
    </message>
    <message>
        <source>%1 — StrataMesh</source>
        <translation>%1 — StrataMesh</translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation>Ouvrir un modèle</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>Ouverture de %1…</translation>
    </message>
    <message>
        <source>No validity problem found</source>
        <translation>Aucun problème de validité détecté</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Prêt</translation>
    </message>
    <message numerus="yes">
        <source>%n validity problem(s) — see Messages</source>
        <translation>
            <numerusform>%n problème de validité — voir Messages</numerusform>
            <numerusform>%n problèmes de validité — voir Messages</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not open the model</source>
        <translation>Impossible d&apos;ouvrir le modèle</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>Impossible d&apos;ouvrir %1</translation>
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
        <translation>%1 triangles</translation>
    </message>
    <message numerus="yes">
        <source>%n line(s)</source>
        <translation>
            <numerusform>%n ligne</numerusform>
            <numerusform>%n lignes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s)</source>
        <translation>
            <numerusform>%n coin</numerusform>
            <numerusform>%n coins</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n region(s)</source>
        <translation>
            <numerusform>%n région</numerusform>
            <numerusform>%n régions</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 opened in %2 s</source>
        <translation>%1 ouvert en %2 s</translation>
    </message>
    <message>
        <source>%1 (box excluded)  ·  %2</source>
        <translation>%1 (hors boîte)  ·  %2</translation>
    </message>
    <message>
        <source>With the box: %1</source>
        <translation>Avec la boîte : %1</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Barre d&apos;outils principale</translation>
    </message>
</context>
<context>
    <name>stratamesh::MessagePanel</name>
    <message>
        <source>Error</source>
        <translation>Erreur</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Avertissement</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Gravité</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Location</source>
        <translation>Emplacement</translation>
    </message>
</context>
<context>
    <name>stratamesh::OpenModelController</name>
    <message>
        <source>Building the sample model</source>
        <translation>Construction du modèle d&apos;exemple</translation>
    </message>
    <message>
        <source>Reading %1</source>
        <translation>Lecture de %1</translation>
    </message>
    <message>
        <source>Recovering lines and corners</source>
        <translation>Reconstruction des lignes et des coins</translation>
    </message>
    <message>
        <source>Checking validity</source>
        <translation>Vérification de la validité</translation>
    </message>
    <message>
        <source>Structural models (*.ml *.ts *.obj *.off);;Gocad Model3d (*.ml);;Gocad TSurf (*.ts);;Wavefront OBJ (*.obj);;Object File Format (*.off);;All files (*)</source>
        <translation>Modèles structuraux (*.ml *.ts *.obj *.off);;Gocad Model3d (*.ml);;Gocad TSurf (*.ts);;Wavefront OBJ (*.obj);;Object File Format (*.off);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Loading stopped without a result</source>
        <translation>Le chargement s&apos;est arrêté sans résultat</translation>
    </message>
    <message>
        <source>Sample model</source>
        <translation>Modèle d&apos;exemple</translation>
    </message>
</context>
</TS>
