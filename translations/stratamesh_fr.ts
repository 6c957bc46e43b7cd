<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
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
    <message>
        <source>Conformal remeshing and analysis of 3D structural models, after J. Pellerin&apos;s PhD thesis. The menus offer:</source>
        <translation>Remaillage conforme et analyse de modèles structuraux 3D, d&apos;après la thèse de doctorat de J. Pellerin. Les menus proposent :</translation>
    </message>
</context>
<context>
    <name>DisabledReason</name>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>GuiOptions</name>
    <message>
        <source>StrataMesh: remeshing and meshing of 3D structural models.</source>
        <translation>StrataMesh : remaillage et maillage de modèles structuraux 3D.</translation>
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
    <message>
        <source>Open the model or the project (.smproj) in &lt;file&gt;.</source>
        <translation>Ouvrir le modèle ou le projet (.smproj) dans &lt;file&gt;.</translation>
    </message>
    <message>
        <source>%1 needs a number in [%2, %3], not &apos;%4&apos;.</source>
        <translation>%1 demande un nombre dans [%2, %3], pas « %4 ».</translation>
    </message>
    <message>
        <source>Unknown step &apos;%1&apos; for --run: use complexity, remesh, tetmesh or hybrid.</source>
        <translation>Étape « %1 » inconnue pour --run : utilisez complexity, remesh, tetmesh ou hybrid.</translation>
    </message>
    <message>
        <source>--sites must follow --run remesh or --run hybrid.</source>
        <translation>--sites doit suivre --run remesh ou --run hybrid.</translation>
    </message>
    <message>
        <source>--cells must follow --run complexity.</source>
        <translation>--cells doit suivre --run complexity.</translation>
    </message>
    <message>
        <source>Unknown colouring &apos;%1&apos; for --colour-by: use entity, min-angle, quality or distance.</source>
        <translation>Coloration « %1 » inconnue pour --colour-by : utilisez entity, min-angle, quality ou distance.</translation>
    </message>
    <message>
        <source>--save-project needs a file name.</source>
        <translation>--save-project demande un nom de fichier.</translation>
    </message>
    <message>
        <source>Load the model, do the steps, save the window as a PNG image in &lt;png&gt; and exit (status 0 when saved, 1 when the image could not be written, 2 when the model could not be opened, 3 when a step failed).</source>
        <translation>Charger le modèle, faire les étapes, enregistrer la fenêtre en image PNG dans &lt;png&gt; et quitter (code 0 si elle est enregistrée, 1 si l’image n’a pas pu être écrite, 2 si le modèle n’a pas pu être ouvert, 3 si une étape a échoué).</translation>
    </message>
    <message>
        <source>Same as --run remesh --sites &lt;n&gt;.</source>
        <translation>Identique à --run remesh --sites &lt;n&gt;.</translation>
    </message>
    <message>
        <source>Same as --run complexity --cells &lt;n&gt;.</source>
        <translation>Identique à --run complexity --cells &lt;n&gt;.</translation>
    </message>
    <message>
        <source>Once the model is open, run &lt;step&gt;: complexity, remesh, tetmesh (the input and the remesh) or hybrid; may be repeated. The steps, --colour-by and --save-project are done in the order given, each once the one before has finished; a failed step stops the others, prints its name and exits with status 3 (after the screenshot, if asked).</source>
        <translation>Une fois le modèle ouvert, lancer &lt;step&gt; : complexity, remesh, tetmesh (l’entrée et le remaillage) ou hybrid ; peut être répété. Les étapes, --colour-by et --save-project sont faites dans l’ordre donné, chacune une fois la précédente terminée ; une étape en échec arrête les suivantes, affiche son nom et quitte avec le code 3 (après la capture d’écran, si elle est demandée).</translation>
    </message>
    <message>
        <source>Number of sites of the --run remesh or --run hybrid just before.</source>
        <translation>Nombre de sites du --run remesh ou --run hybrid qui précède.</translation>
    </message>
    <message>
        <source>Number of cells of the --run complexity just before.</source>
        <translation>Nombre de cellules du --run complexity qui précède.</translation>
    </message>
    <message>
        <source>Colour both views by &lt;colouring&gt;: entity, min-angle, quality or distance (needs a remesh before).</source>
        <translation>Colorer les deux vues selon &lt;colouring&gt; : entity, min-angle, quality ou distance (demande un remaillage avant).</translation>
    </message>
    <message>
        <source>Save the runs made so far as the project &lt;project&gt;.smproj.</source>
        <translation>Enregistrer les calculs faits jusque-là dans le projet &lt;project&gt;.smproj.</translation>
    </message>
    <message>
        <source>the model could not be opened: no step was done.</source>
        <translation>le modèle n’a pas pu être ouvert : aucune étape n’a été faite.</translation>
    </message>
</context>
<context>
    <name>ReviewCommand</name>
    <message>
        <source>Note on record %1</source>
        <translation>Note sur l’enregistrement %1</translation>
    </message>
    <message>
        <source>Accept record %1</source>
        <translation>Accepter l’enregistrement %1</translation>
    </message>
    <message>
        <source>Flag record %1</source>
        <translation>Signaler l’enregistrement %1</translation>
    </message>
    <message>
        <source>Reopen record %1</source>
        <translation>Rouvrir l’enregistrement %1</translation>
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
    <name>stratamesh::ClipControls</name>
    <message>
        <source>C&amp;lip plane</source>
        <translation>P&amp;lan de coupe</translation>
    </message>
    <message>
        <source>Show only the cells on one side of a plane, to see inside the mesh</source>
        <translation>Ne montrer que les cellules d&apos;un côté d&apos;un plan, pour voir l&apos;intérieur du maillage</translation>
    </message>
    <message>
        <source>North–south section (x)</source>
        <translation>Coupe nord–sud (x)</translation>
    </message>
    <message>
        <source>East–west section (y)</source>
        <translation>Coupe est–ouest (y)</translation>
    </message>
    <message>
        <source>Horizontal section (z)</source>
        <translation>Coupe horizontale (z)</translation>
    </message>
    <message>
        <source>Position of the plane across the mesh</source>
        <translation>Position du plan à travers le maillage</translation>
    </message>
</context>
<context>
    <name>stratamesh::ComparisonTable</name>
    <message>
        <source>Input</source>
        <translation>Entrée</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Sortie</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>Surfaces</source>
        <translation>Surfaces</translation>
    </message>
    <message>
        <source>Lines</source>
        <translation>Lignes</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Coins</translation>
    </message>
    <message>
        <source>Min angle (°)</source>
        <translation>Angle min. (°)</translation>
    </message>
    <message>
        <source>Angle &lt; 30° (% triangles)</source>
        <translation>Angle &lt; 30° (% des triangles)</translation>
    </message>
    <message>
        <source>Mean quality Q</source>
        <translation>Qualité moyenne Q</translation>
    </message>
    <message>
        <source>Hausdorff (% bbox diagonal)</source>
        <translation>Hausdorff (% diagonale de la boîte)</translation>
    </message>
    <message>
        <source>Sampling time (s)</source>
        <translation>Temps d&apos;échantillonnage (s)</translation>
    </message>
    <message>
        <source>Mesh building time (s)</source>
        <translation>Temps de construction du maillage (s)</translation>
    </message>
    <message>
        <source>As thesis Table 4.2: entities counted without the box; Q is 1 for an equilateral triangle.</source>
        <translation>Comme la table 4.2 de la thèse : entités comptées sans la boîte ; Q vaut 1 pour un triangle équilatéral.</translation>
    </message>
    <message>
        <source>Min angle</source>
        <translation>Angle min.</translation>
    </message>
    <message>
        <source>Smallest angle of each triangle, in % of the triangles</source>
        <translation>Plus petit angle de chaque triangle, en % des triangles</translation>
    </message>
    <message>
        <source>Q</source>
        <translation>Q</translation>
    </message>
    <message>
        <source>Quality Q of each triangle (1: equilateral), in % of the triangles</source>
        <translation>Qualité Q de chaque triangle (1 : équilatéral), en % des triangles</translation>
    </message>
    <message>
        <source>Min dihedral</source>
        <translation>Dièdre min.</translation>
    </message>
    <message>
        <source>Smallest dihedral angle of each tetrahedron, in % of the tets</source>
        <translation>Plus petit angle dièdre de chaque tétraèdre, en % des tétraèdres</translation>
    </message>
    <message>
        <source>Radius ratio</source>
        <translation>Rapport des rayons</translation>
    </message>
    <message>
        <source>Radius ratio 3r/R of each tetrahedron (1: regular, 0: flat), in % of the tets</source>
        <translation>Rapport des rayons 3r/R de chaque tétraèdre (1 : régulier, 0 : plat), en % des tétraèdres</translation>
    </message>
    <message>
        <source>Remesh</source>
        <translation>Remaillage</translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityController</name>
    <message>
        <source>Measuring complexity</source>
        <translation>Mesure de la complexité</translation>
    </message>
    <message>
        <source>The complexity analysis stopped without a result</source>
        <translation>L&apos;analyse de complexité s&apos;est arrêtée sans résultat</translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityDialog</name>
    <message>
        <source>Complexity Analysis</source>
        <translation>Analyse de complexité</translation>
    </message>
    <message>
        <source>&amp;Analyse</source>
        <translation>&amp;Analyser</translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityPanel</name>
    <message>
        <source>%1 of %2 cells drawn</source>
        <translation>%1 cellules dessinées sur %2</translation>
    </message>
    <message>
        <source>Regions</source>
        <translation>Régions</translation>
    </message>
    <message>
        <source>Surfaces</source>
        <translation>Surfaces</translation>
    </message>
    <message>
        <source>Lines</source>
        <translation>Lignes</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Coins</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>Total</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Geometric</source>
        <translation>Géométrique</translation>
    </message>
    <message>
        <source>Size var. coeff.</source>
        <translation>Coeff. var. taille</translation>
    </message>
    <message>
        <source>Number of elements, box excluded (thesis Table 3.1)</source>
        <translation>Nombre d&apos;éléments, hors boîte (thèse, tableau 3.1)</translation>
    </message>
    <message>
        <source>Sum of C_t + C_f + C_e + C_a over the elements (thesis Table 3.2)</source>
        <translation>Somme de C_t + C_f + C_e + C_a sur les éléments (thèse, tableau 3.2)</translation>
    </message>
    <message>
        <source>Standard deviation / mean of the volumes, areas and lengths (thesis Table 3.3)</source>
        <translation>Écart type / moyenne des volumes, aires et longueurs (thèse, tableau 3.3)</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Cellules</translation>
    </message>
    <message>
        <source>Q10</source>
        <translation>Q10</translation>
    </message>
    <message>
        <source>Q50 (median)</source>
        <translation>Q50 (médiane)</translation>
    </message>
    <message>
        <source>Q90</source>
        <translation>Q90</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Moyenne</translation>
    </message>
    <message>
        <source>Var. coeff.</source>
        <translation>Coeff. var.</translation>
    </message>
    <message>
        <source>Show the &amp;heat map of elements per cell</source>
        <translation>Afficher la &amp;carte de chaleur des éléments par cellule</translation>
    </message>
    <message>
        <source>Draw cells with at &amp;least</source>
        <translation>Dessiner les cellules d&apos;au &amp;moins</translation>
    </message>
    <message>
        <source> elements</source>
        <translation> éléments</translation>
    </message>
    <message>
        <source>Cells meeting fewer model elements are not drawn, so the model stays visible.</source>
        <translation>Les cellules rencontrant moins d&apos;éléments du modèle ne sont pas dessinées, pour que le modèle reste visible.</translation>
    </message>
    <message>
        <source>Global measures (thesis Tables 3.1–3.3): none yet.</source>
        <translation>Mesures globales (thèse, tableaux 3.1–3.3) : aucune pour l&apos;instant.</translation>
    </message>
    <message>
        <source>Elements per cell (thesis Table 3.4): none yet.</source>
        <translation>Éléments par cellule (thèse, tableau 3.4) : aucun pour l&apos;instant.</translation>
    </message>
    <message>
        <source>Global measures, box excluded (thesis Tables 3.1–3.3); geometric with h = %1 m, α = %2°.</source>
        <translation>Mesures globales, hors boîte (thèse, tableaux 3.1–3.3) ; géométrique avec h = %1 m, α = %2°.</translation>
    </message>
    <message>
        <source>Elements per cell (thesis Table 3.4): none.</source>
        <translation>Éléments par cellule (thèse, tableau 3.4) : aucun.</translation>
    </message>
    <message numerus="yes">
        <source>Elements per cell (thesis Table 3.4), seed %1, %n Lloyd iteration(s); %2 cell(s) outside the model left out of the statistics.</source>
        <translation>
            <numerusform>Éléments par cellule (thèse, tableau 3.4), graine %1, %n itération de Lloyd ; %2 cellule(s) hors du modèle exclue(s) des statistiques.</numerusform>
            <numerusform>Éléments par cellule (thèse, tableau 3.4), graine %1, %n itérations de Lloyd ; %2 cellule(s) hors du modèle exclue(s) des statistiques.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stratamesh::ComplexityWorkflow</name>
    <message>
        <source>&amp;Complexity…</source>
        <translation>&amp;Complexité…</translation>
    </message>
    <message>
        <source>Measure the complexity of the model and show the elements per cell as a heat map</source>
        <translation>Mesurer la complexité du modèle et afficher les éléments par cellule en carte de chaleur</translation>
    </message>
    <message>
        <source>C&amp;ancel Complexity Analysis</source>
        <translation>A&amp;nnuler l&apos;analyse de complexité</translation>
    </message>
    <message>
        <source>Stop the complexity analysis</source>
        <translation>Arrêter l&apos;analyse de complexité</translation>
    </message>
    <message>
        <source>&amp;Export Complexity Cells…</source>
        <translation>&amp;Exporter les cellules de complexité…</translation>
    </message>
    <message>
        <source>Write the cells with their element counts as a VTK unstructured grid (.vtu)</source>
        <translation>Écrire les cellules avec leur nombre d&apos;éléments en grille non structurée VTK (.vtu)</translation>
    </message>
    <message>
        <source>Complexity</source>
        <translation>Complexité</translation>
    </message>
    <message>
        <source>&amp;Complexity</source>
        <translation>&amp;Complexité</translation>
    </message>
    <message>
        <source>Elements
per cell</source>
        <translation>Éléments
par cellule</translation>
    </message>
    <message>
        <source>Measuring the complexity of %1…</source>
        <translation>Mesure de la complexité de %1…</translation>
    </message>
    <message>
        <source>Complexity measured with %1 cells in %2 s: %3 elements per cell at most, %4 on average</source>
        <translation>Complexité mesurée avec %1 cellules en %2 s : %3 éléments par cellule au plus, %4 en moyenne</translation>
    </message>
    <message>
        <source>Complexity measured — see Complexity</source>
        <translation>Complexité mesurée — voir Complexité</translation>
    </message>
    <message>
        <source>Complexity analysis failed: %1</source>
        <translation>Échec de l&apos;analyse de complexité : %1</translation>
    </message>
    <message>
        <source>Complexity analysis failed — see Messages</source>
        <translation>Échec de l&apos;analyse de complexité — voir Messages</translation>
    </message>
    <message>
        <source>Complexity analysis cancelled</source>
        <translation>Analyse de complexité annulée</translation>
    </message>
    <message>
        <source>Export Complexity Cells</source>
        <translation>Exporter les cellules de complexité</translation>
    </message>
    <message>
        <source>VTK unstructured grid (*.vtu)</source>
        <translation>Grille non structurée VTK (*.vtu)</translation>
    </message>
    <message>
        <source>Complexity cells exported</source>
        <translation>Cellules de complexité exportées</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Could not export the complexity cells</source>
        <translation>Impossible d&apos;exporter les cellules de complexité</translation>
    </message>
    <message>
        <source>Complexity analysis cancelled: no result, the model is unchanged</source>
        <translation>Analyse de complexité annulée : aucun résultat, le modèle est inchangé</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
    </message>
    <message>
        <source>no complexity analysis is running</source>
        <translation>aucune analyse de complexité n&apos;est en cours</translation>
    </message>
    <message>
        <source>no complexity analysis yet</source>
        <translation>pas encore d&apos;analyse de complexité</translation>
    </message>
</context>
<context>
    <name>stratamesh::Core</name>
    <message>
        <source>two distinct points %1 apart at %2, closer than a volume mesher&apos;s merge tolerance (TetGen merges them)</source>
        <translation>deux points distincts à %1 l&apos;un de l&apos;autre en %2, plus proches que la tolérance de fusion d&apos;un mailleur volumique (TetGen les fusionne)</translation>
    </message>
    <message>
        <source>triangle %1 of %2 and triangle %3 of %4 intersect near %5</source>
        <translation>le triangle %1 de %2 et le triangle %3 de %4 se coupent près de %5</translation>
    </message>
    <message>
        <source>region %1 has no boundary surface</source>
        <translation>la région %1 n&apos;a aucune surface de bord</translation>
    </message>
    <message>
        <source>%1 lists the same side of surface %2 twice</source>
        <translation>%1 cite deux fois le même côté de la surface %2</translation>
    </message>
    <message>
        <source>the boundary of the Universe is not closed: %1 edges are used an odd number of times</source>
        <translation>le bord de l&apos;Univers n&apos;est pas fermé : %1 arêtes sont utilisées un nombre impair de fois</translation>
    </message>
    <message>
        <source>the boundary of region %2 is not closed: %1 edges are used an odd number of times</source>
        <translation>le bord de la région %2 n&apos;est pas fermé : %1 arêtes sont utilisées un nombre impair de fois</translation>
    </message>
    <message>
        <source>the sides of the Universe are inconsistent: %1 edges are not run as often one way as the other</source>
        <translation>les côtés de l&apos;Univers sont incohérents : %1 arêtes ne sont pas parcourues autant de fois dans un sens que dans l&apos;autre</translation>
    </message>
    <message>
        <source>the sides of region %2 are inconsistent: %1 edges are not run as often one way as the other</source>
        <translation>les côtés de la région %2 sont incohérents : %1 arêtes ne sont pas parcourues autant de fois dans un sens que dans l&apos;autre</translation>
    </message>
    <message>
        <source>the sides of the Universe disagree with the surface normals: its volume is %1 (expected negative; region on the side the normal points to is &apos;+&apos;)</source>
        <translation>les côtés de l&apos;Univers contredisent les normales des surfaces : son volume vaut %1 (négatif attendu ; la région du côté où pointe la normale est « + »)</translation>
    </message>
    <message>
        <source>the sides of region %2 disagree with the surface normals: its volume is %1 (expected positive; region on the side the normal points to is &apos;+&apos;)</source>
        <translation>les côtés de la région %2 contredisent les normales des surfaces : son volume vaut %1 (positif attendu ; la région du côté où pointe la normale est « + »)</translation>
    </message>
    <message>
        <source>side %1 of surface %2 is claimed by %3 regions</source>
        <translation>le côté %1 de la surface %2 est revendiqué par %3 régions</translation>
    </message>
    <message>
        <source>side %1 of surface %2 belongs to no region nor to the Universe</source>
        <translation>le côté %1 de la surface %2 n&apos;appartient à aucune région ni à l&apos;Univers</translation>
    </message>
    <message>
        <source>%1 of the %2 edges of %3 are on the border of surface %4 only: the model is not sealed there (it touches no other surface)</source>
        <translation>%1 des %2 arêtes de %3 sont au bord de la seule surface %4 : le modèle n&apos;est pas étanche à cet endroit (elle ne touche aucune autre surface)</translation>
    </message>
    <message>
        <source>an edge of surface %1 has %2 triangles around it</source>
        <translation>une arête de la surface %1 est entourée de %2 triangles</translation>
    </message>
    <message>
        <source>triangle %1 of %2 uses one vertex twice</source>
        <translation>le triangle %1 de %2 utilise deux fois le même sommet</translation>
    </message>
    <message>
        <source>triangle %1 of %2 has two corners at the same position</source>
        <translation>le triangle %1 de %2 a deux sommets à la même position</translation>
    </message>
    <message>
        <source>triangle %1 of %2 has zero area (collinear corners)</source>
        <translation>le triangle %1 de %2 a une aire nulle (sommets alignés)</translation>
    </message>
    <message>
        <source>triangle %1 of %2 lies on the same three points as triangle %3 of %4</source>
        <translation>le triangle %1 de %2 repose sur les trois mêmes points que le triangle %3 de %4</translation>
    </message>
    <message>
        <source>two triangles of surface %1 run their common edge the same way (flipped normals)</source>
        <translation>deux triangles de la surface %1 parcourent leur arête commune dans le même sens (normales inversées)</translation>
    </message>
    <message>
        <source>sliver shared by two surfaces: its shortest edge collapsed (Alg 4.4)</source>
        <translation>triangle plat partagé par deux surfaces : sa plus courte arête contractée (alg. 4.4)</translation>
    </message>
    <message>
        <source>points closer than the resolution merged to undo intersecting triangles</source>
        <translation>points plus proches que la résolution fusionnés pour défaire des triangles sécants</translation>
    </message>
    <message>
        <source>output triangles still intersect after flips and vertex moves</source>
        <translation>des triangles de la sortie se coupent encore après basculements et déplacements de sommets</translation>
    </message>
    <message>
        <source>valence-3 vertex of a tiny cell removed (Fig 4.8a)</source>
        <translation>sommet de valence 3 d&apos;une cellule minuscule supprimé (fig. 4.8a)</translation>
    </message>
    <message>
        <source>degenerate triangle on a free border removed (Fig 4.8b)</source>
        <translation>triangle dégénéré sur un bord libre supprimé (fig. 4.8b)</translation>
    </message>
    <message>
        <source>cap along a contact: vertex inserted into the contact (Alg 4.4, configuration 6)</source>
        <translation>triangle obtus le long d&apos;un contact : sommet inséré dans le contact (alg. 4.4, configuration 6)</translation>
    </message>
    <message>
        <source>surface entirely below the resolution</source>
        <translation>surface entièrement sous la résolution</translation>
    </message>
    <message>
        <source>a connected part of the surface disappeared</source>
        <translation>une partie connexe de la surface a disparu</translation>
    </message>
    <message>
        <source>the surface was split into more parts: this one is separate</source>
        <translation>la surface a été coupée en davantage de parties : celle-ci est séparée</translation>
    </message>
    <message>
        <source>contact or border line not in the output</source>
        <translation>ligne de contact ou de bord absente de la sortie</translation>
    </message>
    <message>
        <source>line of the output with no counterpart in the input</source>
        <translation>ligne de la sortie sans équivalent dans l&apos;entrée</translation>
    </message>
    <message>
        <source>corner not in the output (distance to the nearest output corner)</source>
        <translation>coin absent de la sortie (distance au coin de sortie le plus proche)</translation>
    </message>
    <message>
        <source>corner of the output with no counterpart in the input</source>
        <translation>coin de la sortie sans équivalent dans l&apos;entrée</translation>
    </message>
    <message>
        <source>corners of one Voronoi cell joined by a line merged (Fig 4.6b)</source>
        <translation>coins d&apos;une même cellule de Voronoï reliés par une ligne fusionnés (fig. 4.6b)</translation>
    </message>
    <message>
        <source>a cell component with more than two points: points merged (Fig 4.6a)</source>
        <translation>une composante de cellule de plus de deux points : points fusionnés (fig. 4.6a)</translation>
    </message>
    <message>
        <source>a cell component with more than two points: its two closest merged (Fig 4.6a)</source>
        <translation>une composante de cellule de plus de deux points : ses deux plus proches fusionnés (fig. 4.6a)</translation>
    </message>
    <message>
        <source>model parts closer than d_resolution merged (Fig 4.7)</source>
        <translation>parties du modèle plus proches que d_resolution fusionnées (fig. 4.7)</translation>
    </message>
    <message>
        <source>strip %1 (%2 m wide, limit %3 m) removed: its two lines merged half-way (Fig 4.7 per strip)</source>
        <translation>bande %1 (%2 m de large, limite %3 m) supprimée : ses deux lignes fusionnées à mi-chemin (fig. 4.7 par bande)</translation>
    </message>
    <message>
        <source>strip %1 (%2 m wide, limit %3 m) removed: its two lines merged onto one of them (Fig 4.7 per strip)</source>
        <translation>bande %1 (%2 m de large, limite %3 m) supprimée : ses deux lignes fusionnées sur l&apos;une d&apos;elles (fig. 4.7 par bande)</translation>
    </message>
    <message>
        <source>strip %1 (%2 m wide, limit %3 m) removed before remeshing</source>
        <translation>bande %1 (%2 m de large, limite %3 m) supprimée avant le remaillage</translation>
    </message>
    <message>
        <source>surfaces %1 and %2 fold over each other at %3: one space between them is on the side of %4 and of %5</source>
        <translation>les surfaces %1 et %2 se replient l&apos;une sur l&apos;autre en %3 : un même espace entre elles est du côté de %4 et de %5</translation>
    </message>
    <message>
        <source>region %1 is in more than one piece: a pocket of volume %2 between %3 at %4 is cut off from it</source>
        <translation>la région %1 est en plusieurs morceaux : une poche de volume %2 entre %3 en %4 en est séparée</translation>
    </message>
    <message>
        <source>no file name given</source>
        <translation>aucun nom de fichier donné</translation>
    </message>
    <message>
        <source>cannot write: it is a folder</source>
        <translation>écriture impossible : c&apos;est un dossier</translation>
    </message>
    <message>
        <source>cannot create a file in folder %1: %2</source>
        <translation>impossible de créer un fichier dans le dossier %1 : %2</translation>
    </message>
    <message>
        <source>internal error: file committed twice</source>
        <translation>erreur interne : fichier validé deux fois</translation>
    </message>
    <message>
        <source>cannot write: %1 (nothing was written)</source>
        <translation>écriture impossible : %1 (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>the temporary file %1 vanished: %2 (nothing was written)</source>
        <translation>le fichier temporaire %1 a disparu : %2 (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>cannot replace the file: %1 (nothing was written)</source>
        <translation>impossible de remplacer le fichier : %1 (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>cells export: array &apos;%1&apos; has %2 values for %3 cells</source>
        <translation>export des cellules : le tableau &apos;%1&apos; a %2 valeurs pour %3 cellules</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>écriture impossible : %1</translation>
    </message>
    <message>
        <source>cannot open: %1</source>
        <translation>ouverture impossible : %1</translation>
    </message>
    <message>
        <source>cannot read the file</source>
        <translation>impossible de lire le fichier</translation>
    </message>
    <message>
        <source>%1 needs %2 bytes but only %3 are left at byte %4</source>
        <translation>%1 demande %2 octets mais il n&apos;en reste que %3 à l&apos;octet %4</translation>
    </message>
    <message>
        <source>not a Geogram file (first chunk is &apos;%1&apos;, expected &apos;HEAD&apos;) at byte %2</source>
        <translation>pas un fichier Geogram (le premier bloc est &apos;%1&apos;, &apos;HEAD&apos; attendu) à l&apos;octet %2</translation>
    </message>
    <message>
        <source>64-bit (GARGANTUA) Geogram files are not supported at byte %1</source>
        <translation>les fichiers Geogram 64 bits (GARGANTUA) ne sont pas pris en charge à l&apos;octet %1</translation>
    </message>
    <message>
        <source>not a Geogram file (magic &apos;%1&apos;) at byte %2</source>
        <translation>pas un fichier Geogram (nombre magique &apos;%1&apos;) à l&apos;octet %2</translation>
    </message>
    <message>
        <source>chunk &apos;%1&apos; claims %2 bytes but only %3 are left at byte %4</source>
        <translation>le bloc &apos;%1&apos; annonce %2 octets mais il n&apos;en reste que %3 à l&apos;octet %4</translation>
    </message>
    <message>
        <source>chunk &apos;%1&apos; has %2 bytes more than its fields at byte %3</source>
        <translation>le bloc &apos;%1&apos; a %2 octets de plus que ses champs à l&apos;octet %3</translation>
    </message>
    <message>
        <source>attribute set &apos;%1&apos; is defined twice at byte %2</source>
        <translation>l&apos;ensemble d&apos;attributs &apos;%1&apos; est défini deux fois à l&apos;octet %2</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; belongs to the undefined set &apos;%2&apos; at byte %3</source>
        <translation>l&apos;attribut &apos;%1&apos; appartient à l&apos;ensemble non défini &apos;%2&apos; à l&apos;octet %3</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; of set &apos;%2&apos; is defined twice at byte %3</source>
        <translation>l&apos;attribut &apos;%1&apos; de l&apos;ensemble &apos;%2&apos; est défini deux fois à l&apos;octet %3</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; of %2 items × %3 bytes is larger than its chunk (%4 bytes left) at byte %5</source>
        <translation>l&apos;attribut &apos;%1&apos; de %2 éléments × %3 octets dépasse son bloc (%4 octets restants) à l&apos;octet %5</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; should hold %2 bytes (%3 items of &apos;%4&apos;) but its chunk holds %5 at byte %6</source>
        <translation>l&apos;attribut &apos;%1&apos; devrait contenir %2 octets (%3 éléments de &apos;%4&apos;) mais son bloc en contient %5 à l&apos;octet %6</translation>
    </message>
    <message>
        <source>CMDL claims %1 strings in %2 bytes at byte %3</source>
        <translation>CMDL annonce %1 chaînes dans %2 octets à l&apos;octet %3</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; has elements of %2 bytes, expected %3 (%4)</source>
        <translation>l&apos;attribut &apos;%1&apos; a des éléments de %2 octets, %3 attendus (%4)</translation>
    </message>
    <message>
        <source>cannot initialise zlib</source>
        <translation>impossible d&apos;initialiser zlib</translation>
    </message>
    <message>
        <source>%1 (after %2 bytes)</source>
        <translation>%1 (après %2 octets)</translation>
    </message>
    <message>
        <source>decompresses to more than 4 GiB (a GeoFile indexes with 32 bits)</source>
        <translation>se décompresse en plus de 4 Gio (un GeoFile indexe sur 32 bits)</translation>
    </message>
    <message>
        <source>Geogram attribute &apos;%1&apos; holds %2 bytes, not %3 items of its set &apos;%4&apos;</source>
        <translation>l&apos;attribut Geogram &apos;%1&apos; contient %2 octets, et non %3 éléments de son ensemble &apos;%4&apos;</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; of &apos;%2&apos; is missing</source>
        <translation>l&apos;attribut &apos;%1&apos; de &apos;%2&apos; est absent</translation>
    </message>
    <message>
        <source>attribute &apos;%1&apos; has dimension %2, expected %3</source>
        <translation>l&apos;attribut &apos;%1&apos; est de dimension %2, %3 attendue</translation>
    </message>
    <message>
        <source>&apos;%1&apos; entry %2 is vertex %3, but the mesh has %4 vertices</source>
        <translation>l&apos;entrée %2 de &apos;%1&apos; est le sommet %3, mais le maillage a %4 sommets</translation>
    </message>
    <message>
        <source>&apos;%1&apos; of item %2 is out of order or beyond the %3 corners</source>
        <translation>&apos;%1&apos; de l&apos;élément %2 est hors d&apos;ordre ou au-delà des %3 coins</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not start at corner 0</source>
        <translation>&apos;%1&apos; ne commence pas au coin 0</translation>
    </message>
    <message>
        <source>%1 items of &apos;%2&apos; need %3 corners, the file has %4</source>
        <translation>%1 éléments de &apos;%2&apos; demandent %3 coins, le fichier en a %4</translation>
    </message>
    <message>
        <source>facet %1 has %2 corners</source>
        <translation>la facette %1 a %2 coins</translation>
    </message>
    <message>
        <source>&apos;GEO::Mesh::cells::cell_type&apos; is not one char per cell</source>
        <translation>&apos;GEO::Mesh::cells::cell_type&apos; n&apos;a pas un caractère par cellule</translation>
    </message>
    <message>
        <source>cell %1 has geogram type %2 (only tets 0, prisms 2 and pyramids 3 are supported)</source>
        <translation>la cellule %1 est de type geogram %2 (seuls les tétraèdres 0, les prismes 2 et les pyramides 3 sont pris en charge)</translation>
    </message>
    <message>
        <source>cell %1 has %2 corners, its type needs %3</source>
        <translation>la cellule %1 a %2 coins, son type en demande %3</translation>
    </message>
    <message>
        <source>unexpected text outside a section: &quot;%1&quot;</source>
        <translation>texte inattendu hors d&apos;une section : &quot;%1&quot;</translation>
    </message>
    <message>
        <source>the file does not start with $MeshFormat: not a Gmsh mesh</source>
        <translation>le fichier ne commence pas par $MeshFormat : ce n&apos;est pas un maillage Gmsh</translation>
    </message>
    <message>
        <source>no $MeshFormat section: not a Gmsh mesh</source>
        <translation>pas de section $MeshFormat : ce n&apos;est pas un maillage Gmsh</translation>
    </message>
    <message>
        <source>expected %1, found &quot;%2&quot;</source>
        <translation>%1 attendu, trouvé &quot;%2&quot;</translation>
    </message>
    <message>
        <source>section $%1 has no %2</source>
        <translation>la section $%1 n&apos;a pas de %2</translation>
    </message>
    <message>
        <source>expected &quot;version file-type data-size&quot; in $MeshFormat</source>
        <translation>&quot;version file-type data-size&quot; attendu dans $MeshFormat</translation>
    </message>
    <message>
        <source>MSH version %1 is not supported (use 4.1 or 2.2)</source>
        <translation>la version MSH %1 n&apos;est pas prise en charge (utilisez 4.1 ou 2.2)</translation>
    </message>
    <message>
        <source>binary MSH files are not supported: save as ASCII</source>
        <translation>les fichiers MSH binaires ne sont pas pris en charge : enregistrez-les en ASCII</translation>
    </message>
    <message>
        <source>expected &quot;dim tag \&quot;name\&quot;&quot;</source>
        <translation>&quot;dim tag \&quot;name\&quot;&quot; attendu</translation>
    </message>
    <message>
        <source>$Entities in an MSH 2 file</source>
        <translation>$Entities dans un fichier MSH 2</translation>
    </message>
    <message>
        <source>expected &quot;numPoints numCurves numSurfaces numVolumes&quot;</source>
        <translation>&quot;numPoints numCurves numSurfaces numVolumes&quot; attendu</translation>
    </message>
    <message>
        <source>entity line too short (missing %1)</source>
        <translation>ligne d&apos;entité trop courte (il manque %1)</translation>
    </message>
    <message>
        <source>negative number of physical tags</source>
        <translation>nombre négatif d&apos;étiquettes physiques</translation>
    </message>
    <message>
        <source>negative number of bounding entities</source>
        <translation>nombre négatif d&apos;entités de bord</translation>
    </message>
    <message>
        <source>expected &quot;x y z&quot;</source>
        <translation>&quot;x y z&quot; attendu</translation>
    </message>
    <message>
        <source>node %1 is defined twice</source>
        <translation>le nœud %1 est défini deux fois</translation>
    </message>
    <message>
        <source>expected &quot;tag x y z&quot;</source>
        <translation>&quot;tag x y z&quot; attendu</translation>
    </message>
    <message>
        <source>expected &quot;numEntityBlocks numNodes minNodeTag maxNodeTag&quot;</source>
        <translation>&quot;numEntityBlocks numNodes minNodeTag maxNodeTag&quot; attendu</translation>
    </message>
    <message>
        <source>expected &quot;entityDim entityTag parametric numNodesInBlock&quot;</source>
        <translation>&quot;entityDim entityTag parametric numNodesInBlock&quot; attendu</translation>
    </message>
    <message>
        <source>the $Nodes header declares %1 nodes, its blocks hold %2</source>
        <translation>l&apos;en-tête de $Nodes déclare %1 nœuds, ses blocs en contiennent %2</translation>
    </message>
    <message>
        <source>element type %1 (%2) is not supported: StrataMesh exchanges points, lines, triangles, tetrahedra, pyramids and prisms</source>
        <translation>le type d&apos;élément %1 (%2) n&apos;est pas pris en charge : StrataMesh échange des points, des lignes, des triangles, des tétraèdres, des pyramides et des prismes</translation>
    </message>
    <message>
        <source>a %1 needs %2 nodes</source>
        <translation>un %1 demande %2 nœuds</translation>
    </message>
    <message>
        <source>element uses node %1, which is not in $Nodes</source>
        <translation>un élément utilise le nœud %1, absent de $Nodes</translation>
    </message>
    <message>
        <source>the %1 uses node %2 twice</source>
        <translation>le %1 utilise deux fois le nœud %2</translation>
    </message>
    <message>
        <source>expected &quot;tag type numTags tags... nodes...&quot;</source>
        <translation>&quot;tag type numTags tags... nodes...&quot; attendu</translation>
    </message>
    <message>
        <source>element line too short for its tags</source>
        <translation>ligne d&apos;élément trop courte pour ses étiquettes</translation>
    </message>
    <message>
        <source>expected &quot;numEntityBlocks numElements minElementTag maxElementTag&quot;</source>
        <translation>&quot;numEntityBlocks numElements minElementTag maxElementTag&quot; attendu</translation>
    </message>
    <message>
        <source>expected &quot;entityDim entityTag elementType numElementsInBlock&quot;</source>
        <translation>&quot;entityDim entityTag elementType numElementsInBlock&quot; attendu</translation>
    </message>
    <message>
        <source>the $Elements header declares %1 elements, its blocks hold %2</source>
        <translation>l&apos;en-tête de $Elements déclare %1 éléments, ses blocs en contiennent %2</translation>
    </message>
    <message>
        <source>%1 has %2 TFACEs but the Model3d header declares %3 for it</source>
        <translation>%1 a %2 TFACE mais l&apos;en-tête Model3d lui en déclare %3</translation>
    </message>
    <message>
        <source>the key triangle of %1 is a triangle of several TFACEs of %2</source>
        <translation>le triangle clé de %1 est un triangle de plusieurs TFACE de %2</translation>
    </message>
    <message>
        <source>cannot match %1 to a TFACE of %2: its key triangle is in no remaining TFACE and the TFACE at its position matches another one</source>
        <translation>impossible d&apos;associer %1 à une TFACE de %2 : son triangle clé n&apos;est dans aucune TFACE restante et la TFACE à sa position correspond à une autre</translation>
    </message>
    <message>
        <source>missing %1</source>
        <translation>valeur manquante : %1</translation>
    </message>
    <message>
        <source>too few values, expected &apos;%1&apos;</source>
        <translation>trop peu de valeurs, &apos;%1&apos; attendu</translation>
    </message>
    <message>
        <source>list of ids of %1 is not ended by 0</source>
        <translation>la liste des identifiants de %1 ne se termine pas par 0</translation>
    </message>
    <message>
        <source>&apos;%1&apos; in the list of %2 is not an integer id</source>
        <translation>&apos;%1&apos; dans la liste de %2 n&apos;est pas un identifiant entier</translation>
    </message>
    <message>
        <source>file ends inside the list of ids of %1 (truncated file?)</source>
        <translation>le fichier se termine dans la liste des identifiants de %1 (fichier tronqué ?)</translation>
    </message>
    <message>
        <source>file ends inside the key triangle of TFACE %1 (truncated file?)</source>
        <translation>le fichier se termine dans le triangle clé de la TFACE %1 (fichier tronqué ?)</translation>
    </message>
    <message>
        <source>TSURF &apos;%1&apos; is declared twice (first at line %2)</source>
        <translation>TSURF &apos;%1&apos; est déclarée deux fois (d&apos;abord à la ligne %2)</translation>
    </message>
    <message>
        <source>TFACE %1 is declared twice (first at line %2)</source>
        <translation>TFACE %1 est déclarée deux fois (d&apos;abord à la ligne %2)</translation>
    </message>
    <message>
        <source>TFACE %1 names TSURF &apos;%2&apos;, which the header does not declare</source>
        <translation>TFACE %1 nomme la TSURF &apos;%2&apos;, que l&apos;en-tête ne déclare pas</translation>
    </message>
    <message>
        <source>TSurf &apos;%1&apos; is not declared by a TSURF line of the Model3d header</source>
        <translation>la TSurf &apos;%1&apos; n&apos;est déclarée par aucune ligne TSURF de l&apos;en-tête Model3d</translation>
    </message>
    <message>
        <source>unnamed TSurf beyond the TSURFs declared by the Model3d header</source>
        <translation>TSurf sans nom au-delà des TSURF déclarées par l&apos;en-tête Model3d</translation>
    </message>
    <message>
        <source>second TSurf object for TSURF &apos;%1&apos; (first at line %2)</source>
        <translation>second objet TSurf pour la TSURF &apos;%1&apos; (le premier à la ligne %2)</translation>
    </message>
    <message>
        <source>TSURF &apos;%1&apos; has no TSurf object in the file (truncated file?)</source>
        <translation>la TSURF &apos;%1&apos; n&apos;a pas d&apos;objet TSurf dans le fichier (fichier tronqué ?)</translation>
    </message>
    <message>
        <source>REGION &apos;%1&apos; names TFACE %2, which the header does not declare</source>
        <translation>REGION &apos;%1&apos; nomme la TFACE %2, que l&apos;en-tête ne déclare pas</translation>
    </message>
    <message>
        <source>REGION id %1 is used twice</source>
        <translation>l&apos;identifiant de REGION %1 est utilisé deux fois</translation>
    </message>
    <message>
        <source>no TSurf object in the file</source>
        <translation>aucun objet TSurf dans le fichier</translation>
    </message>
    <message>
        <source>%1 started at line %2 is not closed by &apos;}&apos; before %3</source>
        <translation>%1 commencé à la ligne %2 n&apos;est pas fermé par &apos;}&apos; avant %3</translation>
    </message>
    <message>
        <source>file ends inside the HEADER block started at line %1</source>
        <translation>le fichier se termine dans le bloc HEADER commencé à la ligne %1</translation>
    </message>
    <message>
        <source>ZPOSITIVE must be Elevation or Depth</source>
        <translation>ZPOSITIVE doit valoir Elevation ou Depth</translation>
    </message>
    <message>
        <source>coordinate system block started at line %1 has no END_ORIGINAL_COORDINATE_SYSTEM</source>
        <translation>le bloc de système de coordonnées commencé à la ligne %1 n&apos;a pas de END_ORIGINAL_COORDINATE_SYSTEM</translation>
    </message>
    <message>
        <source>file ends inside the coordinate system block started at line %1</source>
        <translation>le fichier se termine dans le bloc de système de coordonnées commencé à la ligne %1</translation>
    </message>
    <message>
        <source>file ends inside the { } block started at line %1</source>
        <translation>le fichier se termine dans le bloc { } commencé à la ligne %1</translation>
    </message>
    <message>
        <source>file ends before %1 closing the block started at line %2</source>
        <translation>le fichier se termine avant le %1 qui ferme le bloc commencé à la ligne %2</translation>
    </message>
    <message>
        <source>GOCAD line without an object type</source>
        <translation>ligne GOCAD sans type d&apos;objet</translation>
    </message>
    <message>
        <source>file ends before the END of %1 (truncated file?)</source>
        <translation>le fichier se termine avant le END de %1 (fichier tronqué ?)</translation>
    </message>
    <message>
        <source>missing END of %1 before the next GOCAD object</source>
        <translation>END de %1 manquant avant l&apos;objet GOCAD suivant</translation>
    </message>
    <message>
        <source>a Model3d object must come first in the file</source>
        <translation>un objet Model3d doit venir en premier dans le fichier</translation>
    </message>
    <message>
        <source>empty file: no GOCAD object</source>
        <translation>fichier vide : aucun objet GOCAD</translation>
    </message>
    <message>
        <source>cannot open the file (missing or not readable)</source>
        <translation>impossible d&apos;ouvrir le fichier (absent ou illisible)</translation>
    </message>
    <message>
        <source>read error</source>
        <translation>erreur de lecture</translation>
    </message>
    <message>
        <source>vertex id %1 is already defined at line %2</source>
        <translation>l&apos;identifiant de sommet %1 est déjà défini à la ligne %2</translation>
    </message>
    <message>
        <source>ATOM %1 refers to vertex %2, which is not defined before it</source>
        <translation>ATOM %1 renvoie au sommet %2, qui n&apos;est pas défini avant lui</translation>
    </message>
    <message>
        <source>TRGL refers to vertex %1, which is not defined in %2</source>
        <translation>TRGL renvoie au sommet %1, qui n&apos;est pas défini dans %2</translation>
    </message>
    <message>
        <source>TRGL uses the same vertex id twice</source>
        <translation>TRGL utilise deux fois le même identifiant de sommet</translation>
    </message>
    <message>
        <source>%1 refers to vertex %2, which is not defined in %3</source>
        <translation>%1 renvoie au sommet %2, qui n&apos;est pas défini dans %3</translation>
    </message>
    <message>
        <source>%1 has no TFACE and no triangle</source>
        <translation>%1 n&apos;a ni TFACE ni triangle</translation>
    </message>
    <message>
        <source>TFACE of %1 has no triangle (empty surface)</source>
        <translation>la TFACE de %1 n&apos;a aucun triangle (surface vide)</translation>
    </message>
    <message>
        <source>the model &apos;%1&apos; has no surface to write</source>
        <translation>le modèle &apos;%1&apos; n&apos;a aucune surface à écrire</translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has no triangle: Gocad cannot hold it</source>
        <translation>la surface &apos;%1&apos; n&apos;a aucun triangle : Gocad ne peut pas la contenir</translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has a triangle using vertex %2 of %3</source>
        <translation>la surface &apos;%1&apos; a un triangle qui utilise le sommet %2 sur %3</translation>
    </message>
    <message>
        <source>region &apos;%1&apos; is bounded by surface %2 of %3</source>
        <translation>la région &apos;%1&apos; est bordée par la surface %2 sur %3</translation>
    </message>
    <message>
        <source>surface %1 does not exist (the model has %2)</source>
        <translation>la surface %1 n&apos;existe pas (le modèle en a %2)</translation>
    </message>
    <message>
        <source>unknown mesh file extension &apos;%1&apos; (use %2)</source>
        <translation>extension de fichier de maillage inconnue &apos;%1&apos; (utilisez %2)</translation>
    </message>
    <message>
        <source>unknown output extension &apos;%1&apos; (use %2)</source>
        <translation>extension de sortie inconnue &apos;%1&apos; (utilisez %2)</translation>
    </message>
    <message>
        <source>a TSolid holds tetrahedra: the surface model &apos;%1&apos; has none (build a volume mesh first)</source>
        <translation>un TSolid contient des tétraèdres : le modèle de surfaces &apos;%1&apos; n&apos;en a aucun (construisez d&apos;abord un maillage volumique)</translation>
    </message>
    <message>
        <source>unknown model file extension &apos;%1&apos; (expected %2)</source>
        <translation>extension de fichier de modèle inconnue &apos;%1&apos; (%2 attendu)</translation>
    </message>
    <message>
        <source>cannot open the file (missing or not a regular file)</source>
        <translation>impossible d&apos;ouvrir le fichier (absent ou pas un fichier ordinaire)</translation>
    </message>
    <message>
        <source>the file holds no surface triangle (an empty model; volume cells alone give no surface)</source>
        <translation>le fichier ne contient aucun triangle de surface (modèle vide ; des cellules volumiques seules ne donnent pas de surface)</translation>
    </message>
    <message>
        <source>internal error: output planned after the commit</source>
        <translation>erreur interne : sortie prévue après la validation</translation>
    </message>
    <message>
        <source>no file name given for the %1</source>
        <translation>aucun nom de fichier donné pour le %1</translation>
    </message>
    <message>
        <source>cannot write the %1: it is a folder</source>
        <translation>impossible d&apos;écrire le %1 : c&apos;est un dossier</translation>
    </message>
    <message>
        <source>the %1 would replace the input file %2: choose another file, or ask to overwrite it (stratamesh-cli: --overwrite); nothing was written</source>
        <translation>le %1 remplacerait le fichier d&apos;entrée %2 : choisissez un autre fichier, ou demandez à l&apos;écraser (stratamesh-cli : --overwrite) ; rien n&apos;a été écrit</translation>
    </message>
    <message>
        <source>named twice: as the %1 and as the %2</source>
        <translation>nommé deux fois : comme %1 et comme %2</translation>
    </message>
    <message>
        <source>cannot write the %1: its folder %2 does not exist (nothing was written)</source>
        <translation>impossible d&apos;écrire le %1 : son dossier %2 n&apos;existe pas (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>cannot write the %1: %2 is not a folder (nothing was written)</source>
        <translation>impossible d&apos;écrire le %1 : %2 n&apos;est pas un dossier (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>cannot write the %1 in folder %2: %3 (nothing was written)</source>
        <translation>impossible d&apos;écrire le %1 dans le dossier %2 : %3 (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>internal error: this output was not planned before the work</source>
        <translation>erreur interne : cette sortie n&apos;a pas été prévue avant le calcul</translation>
    </message>
    <message>
        <source>internal error: output written after the commit</source>
        <translation>erreur interne : sortie écrite après la validation</translation>
    </message>
    <message>
        <source>cannot write the %1</source>
        <translation>impossible d&apos;écrire le %1</translation>
    </message>
    <message>
        <source>cannot write the %1: %2 (nothing was written)</source>
        <translation>impossible d&apos;écrire le %1 : %2 (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>internal error: outputs committed twice</source>
        <translation>erreur interne : sorties validées deux fois</translation>
    </message>
    <message>
        <source>internal error: the %1 was never written (nothing was written)</source>
        <translation>erreur interne : le %1 n&apos;a jamais été écrit (rien n&apos;a été écrit)</translation>
    </message>
    <message>
        <source>entry missing from the archive (mesh_entities.txt lists %1 %2)</source>
        <translation>entrée absente de l&apos;archive (mesh_entities.txt indique %1 %2)</translation>
    </message>
    <message>
        <source>no such entity: mesh_entities.txt says &apos;Nb %1 %2&apos;</source>
        <translation>entité inexistante : mesh_entities.txt indique &apos;Nb %1 %2&apos;</translation>
    </message>
    <message>
        <source>the file ends before the %1 line</source>
        <translation>le fichier se termine avant la ligne %1</translation>
    </message>
    <message>
        <source>expected %1 (a non-negative integer), found &apos;%2&apos;</source>
        <translation>%1 attendu (un entier positif ou nul), trouvé &apos;%2&apos;</translation>
    </message>
    <message>
        <source>&apos;Version&apos; without a number</source>
        <translation>&apos;Version&apos; sans numéro</translation>
    </message>
    <message>
        <source>unknown .gm version %1 (versions 0, 1 and 2 are known)</source>
        <translation>version .gm %1 inconnue (les versions 0, 1 et 2 sont connues)</translation>
    </message>
    <message>
        <source>only 3D GeoModels are supported (Dimension 3)</source>
        <translation>seuls les GeoModels 3D sont pris en charge (Dimension 3)</translation>
    </message>
    <message>
        <source>&apos;Nb&apos; line needs an entity type and a count</source>
        <translation>une ligne &apos;Nb&apos; demande un type d&apos;entité et un nombre</translation>
    </message>
    <message>
        <source>unknown mesh entity type &apos;%1&apos;</source>
        <translation>type d&apos;entité de maillage inconnu &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Nb %1 %2 is more than the file&apos;s %3 lines can describe</source>
        <translation>Nb %1 %2 dépasse ce que les %3 lignes du fichier peuvent décrire</translation>
    </message>
    <message>
        <source>second &apos;Nb %1&apos; line</source>
        <translation>seconde ligne &apos;Nb %1&apos;</translation>
    </message>
    <message>
        <source>%1 line has %2 fields, version %3 needs %4</source>
        <translation>la ligne %1 a %2 champs, la version %3 en demande %4</translation>
    </message>
    <message>
        <source>%1 %2 is beyond &apos;Nb %1 %3&apos;</source>
        <translation>%1 %2 est au-delà de &apos;Nb %1 %3&apos;</translation>
    </message>
    <message>
        <source>%1 %2 is defined twice</source>
        <translation>%1 %2 est défini deux fois</translation>
    </message>
    <message>
        <source>expected a signed surface id like +3 or -3, found &apos;%1&apos;</source>
        <translation>identifiant de surface signé attendu, comme +3 ou -3, trouvé &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1 has %2 %3 as boundary, but &apos;Nb %2&apos; is %4</source>
        <translation>%1 a %2 %3 comme bord, mais &apos;Nb %2&apos; vaut %4</translation>
    </message>
    <message>
        <source>&apos;Nb %1 %2&apos; but %1 %3 is never described</source>
        <translation>&apos;Nb %1 %2&apos; mais %1 %3 n&apos;est jamais décrit</translation>
    </message>
    <message>
        <source>the GeoModel has no surface</source>
        <translation>le GeoModel n&apos;a aucune surface</translation>
    </message>
    <message>
        <source>Universe has surface %1 as boundary, beyond &apos;Nb Surface&apos;</source>
        <translation>Universe a la surface %1 comme bord, au-delà de &apos;Nb Surface&apos;</translation>
    </message>
    <message>
        <source>geological entity line needs a type, an id, a name and a feature</source>
        <translation>une ligne d&apos;entité géologique demande un type, un identifiant, un nom et une nature</translation>
    </message>
    <message>
        <source>%1 &apos;%2&apos; has %3 %4 as child, but mesh_entities.txt has %5</source>
        <translation>%1 &apos;%2&apos; a %3 %4 comme enfant, mais mesh_entities.txt en a %5</translation>
    </message>
    <message>
        <source>a corner has one vertex, this one has %1</source>
        <translation>un coin a un seul sommet, celui-ci en a %1</translation>
    </message>
    <message>
        <source>a line is a chain of edges, this one has %1 vertices and %2 edges</source>
        <translation>une ligne est une chaîne d&apos;arêtes, celle-ci a %1 sommets et %2 arêtes</translation>
    </message>
    <message>
        <source>surface without facets</source>
        <translation>surface sans facettes</translation>
    </message>
    <message>
        <source>compareRingMeshTopology needs the recovered topology (recoverTopology)</source>
        <translation>compareRingMeshTopology demande la topologie reconstruite (recoverTopology)</translation>
    </message>
    <message>
        <source>a line without vertices</source>
        <translation>une ligne sans sommets</translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has no triangle</source>
        <translation>la surface &apos;%1&apos; n&apos;a aucun triangle</translation>
    </message>
    <message>
        <source>cell %1 has no region: a GeoModel stores cells per region</source>
        <translation>la cellule %1 n&apos;a pas de région : un GeoModel range les cellules par région</translation>
    </message>
    <message>
        <source>bad element count</source>
        <translation>nombre d&apos;éléments invalide</translation>
    </message>
    <message>
        <source>element %1 declares %2 items, more than the file of %3 bytes can hold</source>
        <translation>l&apos;élément %1 déclare %2 entrées, plus que le fichier de %3 octets ne peut en contenir</translation>
    </message>
    <message>
        <source>OpenMesh could not read this file as a surface mesh</source>
        <translation>OpenMesh n&apos;a pas pu lire ce fichier comme un maillage de surface</translation>
    </message>
    <message>
        <source>non-manifold faces: %1 vertices in the file, %2 after reading (save as ASCII PLY, which keeps them)</source>
        <translation>faces non manifold : %1 sommets dans le fichier, %2 après lecture (enregistrez en PLY ASCII, qui les conserve)</translation>
    </message>
    <message>
        <source>%1 face(s) could not be added (degenerate or non-manifold faces)</source>
        <translation>%1 face(s) n&apos;ont pas pu être ajoutées (faces dégénérées ou non manifold)</translation>
    </message>
    <message>
        <source>expected &quot;element NAME COUNT&quot;</source>
        <translation>&quot;element NAME COUNT&quot; attendu</translation>
    </message>
    <message>
        <source>property before any element</source>
        <translation>propriété avant tout élément</translation>
    </message>
    <message>
        <source>expected &quot;property TYPE NAME&quot;</source>
        <translation>&quot;property TYPE NAME&quot; attendu</translation>
    </message>
    <message>
        <source>line too short for the properties of %1</source>
        <translation>ligne trop courte pour les propriétés de %1</translation>
    </message>
    <message>
        <source>line too short for its list</source>
        <translation>ligne trop courte pour sa liste</translation>
    </message>
    <message>
        <source>face uses vertex %1 of %2 (numbered from 0)</source>
        <translation>une face utilise le sommet %1 sur %2 (numérotés à partir de 0)</translation>
    </message>
    <message>
        <source>vertices without x, y and z</source>
        <translation>sommets sans x, y et z</translation>
    </message>
    <message>
        <source>a face needs three vertices</source>
        <translation>une face demande trois sommets</translation>
    </message>
    <message>
        <source>not a PLY file: the first line is not &quot;ply&quot;</source>
        <translation>pas un fichier PLY : la première ligne n&apos;est pas &quot;ply&quot;</translation>
    </message>
    <message>
        <source>unknown PLY format &quot;%1&quot;</source>
        <translation>format PLY inconnu &quot;%1&quot;</translation>
    </message>
    <message>
        <source>the PLY header has no end_header</source>
        <translation>l&apos;en-tête PLY n&apos;a pas de end_header</translation>
    </message>
    <message>
        <source>the PLY header has no format line</source>
        <translation>l&apos;en-tête PLY n&apos;a pas de ligne format</translation>
    </message>
    <message>
        <source>cannot open the file</source>
        <translation>impossible d&apos;ouvrir le fichier</translation>
    </message>
    <message>
        <source>no triangle in the file</source>
        <translation>aucun triangle dans le fichier</translation>
    </message>
    <message>
        <source>an ASCII STL file starts with &quot;solid&quot;</source>
        <translation>un fichier STL ASCII commence par &quot;solid&quot;</translation>
    </message>
    <message>
        <source>expected &quot;%1&quot;, found &quot;%2&quot;</source>
        <translation>&quot;%1&quot; attendu, trouvé &quot;%2&quot;</translation>
    </message>
    <message>
        <source>text after endsolid: &quot;%1&quot;</source>
        <translation>texte après endsolid : &quot;%1&quot;</translation>
    </message>
    <message>
        <source>expected &quot;facet&quot; or &quot;endsolid&quot;, found &quot;%1&quot;</source>
        <translation>&quot;facet&quot; ou &quot;endsolid&quot; attendu, trouvé &quot;%1&quot;</translation>
    </message>
    <message>
        <source>facet %1 has more than three vertices</source>
        <translation>la facette %1 a plus de trois sommets</translation>
    </message>
    <message>
        <source>expected &quot;endloop&quot;, found &quot;%1&quot;</source>
        <translation>&quot;endloop&quot; attendu, trouvé &quot;%1&quot;</translation>
    </message>
    <message>
        <source>facet %1 has two equal corners (degenerate facet)</source>
        <translation>la facette %1 a deux coins égaux (facette dégénérée)</translation>
    </message>
    <message>
        <source>file ends before endsolid (truncated file?)</source>
        <translation>le fichier se termine avant endsolid (fichier tronqué ?)</translation>
    </message>
    <message>
        <source>binary STL of %1 bytes, its header announces %2 facets (%3 bytes): truncated or not an STL file</source>
        <translation>STL binaire de %1 octets, son en-tête annonce %2 facettes (%3 octets) : fichier tronqué ou pas un STL</translation>
    </message>
    <message>
        <source>neither an ASCII STL (starting with &quot;solid&quot;) nor a binary STL (84 bytes or more)</source>
        <translation>ni un STL ASCII (commençant par &quot;solid&quot;) ni un STL binaire (84 octets ou plus)</translation>
    </message>
    <message>
        <source>a vertex needs three coordinates</source>
        <translation>un sommet demande trois coordonnées</translation>
    </message>
    <message>
        <source>coordinate &apos;%1&apos; is not a number</source>
        <translation>la coordonnée &apos;%1&apos; n&apos;est pas un nombre</translation>
    </message>
    <message>
        <source>face vertex &apos;%1&apos; is not an index</source>
        <translation>le sommet de face &apos;%1&apos; n&apos;est pas un indice</translation>
    </message>
    <message>
        <source>face uses vertex %1 (numbered from 1, or back from -1)</source>
        <translation>une face utilise le sommet %1 (numérotés à partir de 1, ou à rebours à partir de -1)</translation>
    </message>
    <message>
        <source>a face needs at least three vertices</source>
        <translation>une face demande au moins trois sommets</translation>
    </message>
    <message>
        <source>face uses vertex %1, the file defines %2</source>
        <translation>une face utilise le sommet %1, le fichier en définit %2</translation>
    </message>
    <message>
        <source>empty file</source>
        <translation>fichier vide</translation>
    </message>
    <message>
        <source>not an OFF file: the first word is not OFF</source>
        <translation>pas un fichier OFF : le premier mot n&apos;est pas OFF</translation>
    </message>
    <message>
        <source>only 3D OFF files are supported</source>
        <translation>seuls les fichiers OFF 3D sont pris en charge</translation>
    </message>
    <message>
        <source>binary OFF files are not supported</source>
        <translation>les fichiers OFF binaires ne sont pas pris en charge</translation>
    </message>
    <message>
        <source>file ends before the vertex and face counts</source>
        <translation>le fichier se termine avant les nombres de sommets et de faces</translation>
    </message>
    <message>
        <source>expected the vertex and face counts</source>
        <translation>nombres de sommets et de faces attendus</translation>
    </message>
    <message>
        <source>invalid vertex and face counts</source>
        <translation>nombres de sommets et de faces invalides</translation>
    </message>
    <message>
        <source>file ends after %1 of %2 vertices</source>
        <translation>le fichier se termine après %1 sommets sur %2</translation>
    </message>
    <message>
        <source>file ends after %1 of %2 faces</source>
        <translation>le fichier se termine après %1 faces sur %2</translation>
    </message>
    <message>
        <source>a face of %1 vertices lists %2</source>
        <translation>une face de %1 sommets en liste %2</translation>
    </message>
    <message>
        <source>face vertex &apos;%1&apos; is not an index from 0 to %2</source>
        <translation>le sommet de face &apos;%1&apos; n&apos;est pas un indice de 0 à %2</translation>
    </message>
    <message>
        <source>not an OBJ or OFF file</source>
        <translation>pas un fichier OBJ ni OFF</translation>
    </message>
    <message>
        <source>the face uses vertex %1 twice (a degenerate face)</source>
        <translation>la face utilise deux fois le sommet %1 (face dégénérée)</translation>
    </message>
    <message>
        <source>non-manifold faces: this face shares an edge with two other faces, or runs along it the same way as its neighbour</source>
        <translation>faces non manifold : cette face partage une arête avec deux autres faces, ou la parcourt dans le même sens que sa voisine</translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; is not manifold at triangle %2: OpenMesh cannot store it as STL</source>
        <translation>la surface &apos;%1&apos; n&apos;est pas manifold au triangle %2 : OpenMesh ne peut pas l&apos;enregistrer en STL</translation>
    </message>
    <message>
        <source>OpenMesh could not write the file</source>
        <translation>OpenMesh n&apos;a pas pu écrire le fichier</translation>
    </message>
    <message>
        <source>unknown surface mesh extension &apos;%1&apos; (use .obj, .off, .stl or .ply)</source>
        <translation>extension de maillage de surface inconnue &apos;%1&apos; (utilisez .obj, .off, .stl ou .ply)</translation>
    </message>
    <message>
        <source>an %1 file holds one surface and the model &apos;%2&apos; has %3: choose one</source>
        <translation>un fichier %1 contient une seule surface et le modèle &apos;%2&apos; en a %3 : choisissez-en une</translation>
    </message>
    <message>
        <source>surface &apos;%1&apos; has a non-finite coordinate</source>
        <translation>la surface &apos;%1&apos; a une coordonnée non finie</translation>
    </message>
    <message>
        <source>surface &apos;%1&apos;: triangle %2 uses vertex %3 of %4</source>
        <translation>surface &apos;%1&apos; : le triangle %2 utilise le sommet %3 sur %4</translation>
    </message>
    <message>
        <source>unexpected end of file (expected %1)</source>
        <translation>fin de fichier inattendue (%1 attendu)</translation>
    </message>
    <message>
        <source>%1 is negative (%2)</source>
        <translation>%1 est négatif (%2)</translation>
    </message>
    <message>
        <source>%1 is %2, more than the remaining %3 bytes of the file can hold</source>
        <translation>%1 vaut %2, plus que les %3 octets restants du fichier ne peuvent en contenir</translation>
    </message>
    <message>
        <source>not a Gocad file (expected &quot;GOCAD TSolid 1&quot;)</source>
        <translation>pas un fichier Gocad (&quot;GOCAD TSolid 1&quot; attendu)</translation>
    </message>
    <message>
        <source>expected a TSolid object, found &quot;%1&quot;</source>
        <translation>objet TSolid attendu, trouvé &quot;%1&quot;</translation>
    </message>
    <message>
        <source>empty file: not a Gocad TSolid</source>
        <translation>fichier vide : ce n&apos;est pas un TSolid Gocad</translation>
    </message>
    <message>
        <source>HEADER without &apos;{&apos;</source>
        <translation>HEADER sans &apos;{&apos;</translation>
    </message>
    <message>
        <source>HEADER block not closed by &apos;}&apos;</source>
        <translation>bloc HEADER non fermé par &apos;}&apos;</translation>
    </message>
    <message>
        <source>block not closed by &apos;}&apos;</source>
        <translation>bloc non fermé par &apos;}&apos;</translation>
    </message>
    <message>
        <source>%1 needs an id and three coordinates</source>
        <translation>%1 demande un identifiant et trois coordonnées</translation>
    </message>
    <message>
        <source>vertex id %1 is used twice</source>
        <translation>l&apos;identifiant de sommet %1 est utilisé deux fois</translation>
    </message>
    <message>
        <source>%1 needs an id and the id of the vertex it shares</source>
        <translation>%1 demande un identifiant et celui du sommet qu&apos;il partage</translation>
    </message>
    <message>
        <source>%1 %2 refers to vertex %3, which is not defined before</source>
        <translation>%1 %2 renvoie au sommet %3, qui n&apos;est pas défini avant</translation>
    </message>
    <message>
        <source>vertex %1 is not defined</source>
        <translation>le sommet %1 n&apos;est pas défini</translation>
    </message>
    <message>
        <source>TETRA needs four vertex ids</source>
        <translation>TETRA demande quatre identifiants de sommets</translation>
    </message>
    <message>
        <source>TETRA uses the same vertex twice</source>
        <translation>TETRA utilise deux fois le même sommet</translation>
    </message>
    <message>
        <source>TRGL outside a MODEL TFACE</source>
        <translation>TRGL hors d&apos;une MODEL TFACE</translation>
    </message>
    <message>
        <source>TRGL needs three vertex ids</source>
        <translation>TRGL demande trois identifiants de sommets</translation>
    </message>
    <message>
        <source>TRGL uses the same vertex twice</source>
        <translation>TRGL utilise deux fois le même sommet</translation>
    </message>
    <message>
        <source>a TSolid needs tetrahedra: the mesh &apos;%1&apos; has no cell</source>
        <translation>un TSolid demande des tétraèdres : le maillage &apos;%1&apos; n&apos;a aucune cellule</translation>
    </message>
    <message>
        <source>a TSolid holds tetrahedra only: the mesh &apos;%1&apos; has %2 prisms and %3 pyramids (use .vtu or .msh)</source>
        <translation>un TSolid ne contient que des tétraèdres : le maillage &apos;%1&apos; a %2 prismes et %3 pyramides (utilisez .vtu ou .msh)</translation>
    </message>
    <message>
        <source>%1 declares %2 values, more than the file of %3 bytes can hold</source>
        <translation>%1 déclare %2 valeurs, plus que le fichier de %3 octets ne peut en contenir</translation>
    </message>
    <message>
        <source>%1 declares %2 values, the file ends after %3</source>
        <translation>%1 déclare %2 valeurs, le fichier se termine après %3</translation>
    </message>
    <message>
        <source>%1 declares %2 values, &quot;%3&quot; comes after %4</source>
        <translation>%1 déclare %2 valeurs, &quot;%3&quot; vient après %4</translation>
    </message>
    <message>
        <source>%1 declares %2 values, the line holds more</source>
        <translation>%1 déclare %2 valeurs, la ligne en contient davantage</translation>
    </message>
    <message>
        <source>%1 declares %2 strings, more than the file of %3 bytes can hold</source>
        <translation>%1 déclare %2 chaînes, plus que le fichier de %3 octets ne peut en contenir</translation>
    </message>
    <message>
        <source>%1 declares %2 strings, the file ends after %3</source>
        <translation>%1 déclare %2 chaînes, le fichier se termine après %3</translation>
    </message>
    <message>
        <source>%1 data is cut short in string %2 of %3</source>
        <translation>les données de %1 s&apos;arrêtent dans la chaîne %2 sur %3</translation>
    </message>
    <message>
        <source>%1 is followed by &apos;%2&apos; on its line</source>
        <translation>%1 est suivi de &apos;%2&apos; sur sa ligne</translation>
    </message>
    <message>
        <source>the file ends before %1</source>
        <translation>le fichier se termine avant %1</translation>
    </message>
    <message>
        <source>%1 needs a count, found &quot;%2&quot;</source>
        <translation>%1 demande un nombre, trouvé &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 declares a negative count %2</source>
        <translation>%1 déclare un nombre négatif %2</translation>
    </message>
    <message>
        <source>%1 has type &apos;%2&apos;, which is not a legacy VTK data type</source>
        <translation>%1 est de type &apos;%2&apos;, qui n&apos;est pas un type de données VTK legacy</translation>
    </message>
    <message>
        <source>%1 has type &apos;%2&apos;: it must hold numbers</source>
        <translation>%1 est de type &apos;%2&apos; : il doit contenir des nombres</translation>
    </message>
    <message>
        <source>not a legacy VTK file: the first line is not &quot;# vtk DataFile Version x.y&quot;</source>
        <translation>pas un fichier VTK legacy : la première ligne n&apos;est pas &quot;# vtk DataFile Version x.y&quot;</translation>
    </message>
    <message>
        <source>the file version &apos;%1&apos; is not x.y</source>
        <translation>la version de fichier &apos;%1&apos; n&apos;est pas de la forme x.y</translation>
    </message>
    <message>
        <source>file version %1.%2 is newer than the 5.1 StrataMesh reads</source>
        <translation>la version de fichier %1.%2 est plus récente que la 5.1 que lit StrataMesh</translation>
    </message>
    <message>
        <source>the file ends before its title line</source>
        <translation>le fichier se termine avant sa ligne de titre</translation>
    </message>
    <message>
        <source>expected ASCII or BINARY after the title, found &quot;%1&quot;</source>
        <translation>ASCII ou BINARY attendu après le titre, trouvé &quot;%1&quot;</translation>
    </message>
    <message>
        <source>expected DATASET after %1, found &quot;%2&quot;</source>
        <translation>DATASET attendu après %1, trouvé &quot;%2&quot;</translation>
    </message>
    <message>
        <source>DATASET %1 is not read by StrataMesh (UNSTRUCTURED_GRID or POLYDATA only)</source>
        <translation>DATASET %1 n&apos;est pas lu par StrataMesh (UNSTRUCTURED_GRID ou POLYDATA seulement)</translation>
    </message>
    <message>
        <source>a second %1 (the first is at line %2)</source>
        <translation>un second %1 (le premier est à la ligne %2)</translation>
    </message>
    <message>
        <source>found &quot;%1&quot; where a keyword belongs: the section before it holds more values than it declares</source>
        <translation>&quot;%1&quot; trouvé à la place d&apos;un mot-clé : la section qui le précède contient plus de valeurs qu&apos;elle n&apos;en déclare</translation>
    </message>
    <message>
        <source>POINTS has type &apos;bit&apos;: it must hold coordinates</source>
        <translation>POINTS est de type &apos;bit&apos; : il doit contenir des coordonnées</translation>
    </message>
    <message>
        <source>POINTS declares %1 points, more than the file of %2 bytes can hold</source>
        <translation>POINTS déclare %1 points, plus que le fichier de %2 octets ne peut en contenir</translation>
    </message>
    <message>
        <source>%1 of a version 5 file goes on with &quot;%2 vtktypeint64&quot; (or vtktypeint32), found &quot;%3&quot;</source>
        <translation>%1 d&apos;un fichier en version 5 se poursuit par &quot;%2 vtktypeint64&quot; (ou vtktypeint32), trouvé &quot;%3&quot;</translation>
    </message>
    <message>
        <source>%1 %2 has type &apos;%3&apos; (vtktypeint64 or vtktypeint32 expected)</source>
        <translation>%1 %2 est de type &apos;%3&apos; (vtktypeint64 ou vtktypeint32 attendu)</translation>
    </message>
    <message>
        <source>%1 declares %2 cells in %3 values: a cell takes one at least</source>
        <translation>%1 déclare %2 cellules dans %3 valeurs : une cellule en prend au moins une</translation>
    </message>
    <message>
        <source>%1 declares %2 values, cell %3 (numbered from 0) runs past them</source>
        <translation>%1 déclare %2 valeurs, la cellule %3 (numérotée à partir de 0) va au-delà</translation>
    </message>
    <message>
        <source>%1 declares %2 values, its %3 cells use %4</source>
        <translation>%1 déclare %2 valeurs, ses %3 cellules en utilisent %4</translation>
    </message>
    <message>
        <source>%1 declares no offsets but %2 connectivity values</source>
        <translation>%1 ne déclare aucun décalage mais %2 valeurs de connectivité</translation>
    </message>
    <message>
        <source>%1 OFFSETS and CONNECTIVITY have different types</source>
        <translation>%1 : OFFSETS et CONNECTIVITY sont de types différents</translation>
    </message>
    <message>
        <source>%1 OFFSETS start at %2, not 0</source>
        <translation>%1 : les OFFSETS commencent à %2, et non à 0</translation>
    </message>
    <message>
        <source>%1 OFFSETS decrease at cell %2 (numbered from 0)</source>
        <translation>%1 : les OFFSETS décroissent à la cellule %2 (numérotée à partir de 0)</translation>
    </message>
    <message>
        <source>%1 OFFSETS end at %2, %3 connectivity values are declared</source>
        <translation>%1 : les OFFSETS finissent à %2, %3 valeurs de connectivité sont déclarées</translation>
    </message>
    <message>
        <source>the data set has no POINTS</source>
        <translation>le jeu de données n&apos;a pas de POINTS</translation>
    </message>
    <message>
        <source>CELLS has no CELL_TYPES to go with it</source>
        <translation>CELLS n&apos;a pas de CELL_TYPES qui l&apos;accompagne</translation>
    </message>
    <message>
        <source>CELL_TYPES has no CELLS to go with it</source>
        <translation>CELL_TYPES n&apos;a pas de CELLS qui l&apos;accompagne</translation>
    </message>
    <message>
        <source>CELL_TYPES declares %1 values, CELLS at line %2 declares %3</source>
        <translation>CELL_TYPES déclare %1 valeurs, CELLS à la ligne %2 en déclare %3</translation>
    </message>
    <message>
        <source>%1 comes after the data of the cells or points: the geometry goes first</source>
        <translation>%1 vient après les données des cellules ou des points : la géométrie doit venir en premier</translation>
    </message>
    <message>
        <source>%1 declares %2 x %3 values, more than the file can hold</source>
        <translation>%1 déclare %2 x %3 valeurs, plus que le fichier ne peut en contenir</translation>
    </message>
    <message>
        <source>%1 has dimension &apos;%2&apos; (1, 2 or 3 expected)</source>
        <translation>%1 est de dimension &apos;%2&apos; (1, 2 ou 3 attendu)</translation>
    </message>
    <message>
        <source>%1 has &apos;%2&apos; components (a number from 1 expected)</source>
        <translation>%1 a &apos;%2&apos; composantes (un nombre à partir de 1 attendu)</translation>
    </message>
    <message>
        <source>%1 goes on with &quot;LOOKUP_TABLE default&quot;, found &quot;%2&quot;</source>
        <translation>%1 se poursuit par &quot;LOOKUP_TABLE default&quot;, trouvé &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 holds %2, not a colour from 0 to 1</source>
        <translation>%1 contient %2, qui n&apos;est pas une couleur de 0 à 1</translation>
    </message>
    <message>
        <source>%1 declares %2 colours, more than the file of %3 bytes can hold</source>
        <translation>%1 déclare %2 couleurs, plus que le fichier de %3 octets ne peut en contenir</translation>
    </message>
    <message>
        <source>%1 declares %2 components (from 1 to 1048576)</source>
        <translation>%1 déclare %2 composantes (de 1 à 1048576)</translation>
    </message>
    <message>
        <source>%1 declares %2 x %3 values, more than the file of %4 bytes can hold</source>
        <translation>%1 déclare %2 x %3 valeurs, plus que le fichier de %4 octets ne peut en contenir</translation>
    </message>
    <message>
        <source>the %1 field data holds %2, not a byte of text</source>
        <translation>les données de champ %1 contiennent %2, qui n&apos;est pas un octet de texte</translation>
    </message>
    <message>
        <source>VTK cannot read it: %1</source>
        <translation>VTK ne peut pas le lire : %1</translation>
    </message>
    <message>
        <source>cell %1 has %2 %3 (expected a whole number from 0 to 2147483647)</source>
        <translation>la cellule %1 a %2 %3 (un entier de 0 à 2147483647 attendu)</translation>
    </message>
    <message>
        <source>unknown VTK extension &apos;%1&apos; (use .vtu, .vtp or .vtk)</source>
        <translation>extension VTK inconnue &apos;%1&apos; (utilisez .vtu, .vtp ou .vtk)</translation>
    </message>
    <message>
        <source>no triangle and no volume cell in the file (empty model)</source>
        <translation>ni triangle ni cellule volumique dans le fichier (modèle vide)</translation>
    </message>
    <message>
        <source>the RegionSides field data names surface %1, which the file does not have</source>
        <translation>les données de champ RegionSides nomment la surface %1, que le fichier n&apos;a pas</translation>
    </message>
    <message>
        <source>the RegionSides field data does not match the regions</source>
        <translation>les données de champ RegionSides ne correspondent pas aux régions</translation>
    </message>
    <message>
        <source>a .vtp file holds surfaces only: the mesh &apos;%1&apos; has %2 volume cells (use .vtu or .vtk)</source>
        <translation>un fichier .vtp ne contient que des surfaces : le maillage &apos;%1&apos; a %2 cellules volumiques (utilisez .vtu ou .vtk)</translation>
    </message>
    <message>
        <source>the header of a compressed array is damaged or too large: %1 blocks of %2 bytes, the last of %3, in a file of %4 bytes</source>
        <translation>l&apos;en-tête d&apos;un tableau compressé est endommagé ou trop grand : %1 blocs de %2 octets, le dernier de %3, dans un fichier de %4 octets</translation>
    </message>
    <message>
        <source>a compressed array states no block but holds data</source>
        <translation>un tableau compressé n&apos;annonce aucun bloc mais contient des données</translation>
    </message>
    <message>
        <source>the header of a compressed array is cut short</source>
        <translation>l&apos;en-tête d&apos;un tableau compressé est tronqué</translation>
    </message>
    <message>
        <source>block %1 of a compressed array states %2 compressed bytes, more than the file of %3 bytes</source>
        <translation>le bloc %1 d&apos;un tableau compressé annonce %2 octets compressés, plus que le fichier de %3 octets</translation>
    </message>
    <message>
        <source>%1 is not a whole number</source>
        <translation>%1 n&apos;est pas un nombre entier</translation>
    </message>
    <message>
        <source>%1 is %2, more than the file of %3 bytes can hold even compressed</source>
        <translation>%1 vaut %2, plus que le fichier de %3 octets ne peut en contenir, même compressé</translation>
    </message>
    <message>
        <source>a DataArray has type &quot;%1&quot;, which is not a VTK type</source>
        <translation>un DataArray est de type &quot;%1&quot;, qui n&apos;est pas un type VTK</translation>
    </message>
    <message>
        <source>not a readable zip archive (missing file, or no zip central directory)</source>
        <translation>pas une archive zip lisible (fichier absent, ou pas de répertoire central zip)</translation>
    </message>
    <message>
        <source>corrupt zip directory after %1 entries: %2</source>
        <translation>répertoire zip corrompu après %1 entrées : %2</translation>
    </message>
    <message>
        <source>entry missing from the archive</source>
        <translation>entrée absente de l&apos;archive</translation>
    </message>
    <message>
        <source>entry cannot be located in the archive</source>
        <translation>entrée introuvable dans l&apos;archive</translation>
    </message>
    <message>
        <source>cannot open the entry: %1</source>
        <translation>impossible d&apos;ouvrir l&apos;entrée : %1</translation>
    </message>
    <message>
        <source>cannot decompress the entry after %1 bytes: %2</source>
        <translation>impossible de décompresser l&apos;entrée après %1 octets : %2</translation>
    </message>
    <message>
        <source>entry larger than %1 bytes</source>
        <translation>entrée de plus de %1 octets</translation>
    </message>
    <message>
        <source>cannot create the zip archive</source>
        <translation>impossible de créer l&apos;archive zip</translation>
    </message>
    <message>
        <source>cannot add the entry to the zip archive</source>
        <translation>impossible d&apos;ajouter l&apos;entrée à l&apos;archive zip</translation>
    </message>
    <message>
        <source>cannot write the entry (disk full?)</source>
        <translation>impossible d&apos;écrire l&apos;entrée (disque plein ?)</translation>
    </message>
    <message>
        <source>cannot finish the entry</source>
        <translation>impossible de terminer l&apos;entrée</translation>
    </message>
    <message>
        <source>cannot finish the zip archive (disk full?)</source>
        <translation>impossible de terminer l&apos;archive zip (disque plein ?)</translation>
    </message>
    <message>
        <source>region %1 lists surface %2 which does not exist</source>
        <translation>la région %1 liste la surface %2, qui n&apos;existe pas</translation>
    </message>
    <message>
        <source>no point strictly inside region %1 was found (is its boundary closed and consistently oriented?)</source>
        <translation>aucun point strictement intérieur à la région %1 n&apos;a été trouvé (son bord est-il fermé et orienté de façon cohérente ?)</translation>
    </message>
    <message>
        <source>the model has no surface to tetrahedralise</source>
        <translation>le modèle n&apos;a aucune surface à tétraédriser</translation>
    </message>
    <message>
        <source>surface %1: triangle %2 has two corners at the same point</source>
        <translation>surface %1 : le triangle %2 a deux coins au même point</translation>
    </message>
    <message>
        <source>cannot create a work folder: %1</source>
        <translation>impossible de créer un dossier de travail : %1</translation>
    </message>
    <message>
        <source>TetGen parameters must be finite and not negative</source>
        <translation>les paramètres de TetGen doivent être finis et positifs ou nuls</translation>
    </message>
    <message>
        <source>not a Gocad file: expected &apos;GOCAD &lt;type&gt;&apos;</source>
        <translation>pas un fichier Gocad : &apos;GOCAD &lt;type&gt;&apos; attendu</translation>
    </message>
    <message>
        <source>expected &apos;GOCAD &lt;type&gt;&apos; to start the next object</source>
        <translation>&apos;GOCAD &lt;type&gt;&apos; attendu pour commencer l&apos;objet suivant</translation>
    </message>
    <message>
        <source>is not finite (non-finite vertex)</source>
        <translation>n&apos;est pas fini (sommet non fini)</translation>
    </message>
    <message>
        <source>is beyond the bound of 1e15 that keeps squared distances and volumes finite</source>
        <translation>dépasse la borne de 1e15 qui garde finis les carrés des distances et les volumes</translation>
    </message>
    <message>
        <source>coordinate %1 %2</source>
        <translation>la coordonnée %1 %2</translation>
    </message>
    <message>
        <source>point %1 (numbered from 0): %2</source>
        <translation>point %1 (numéroté à partir de 0) : %2</translation>
    </message>
    <message>
        <source>node %1: %2</source>
        <translation>nœud %1 : %2</translation>
    </message>
    <message>
        <source>%2 %1 is not a number</source>
        <translation>%2 %1 n&apos;est pas un nombre</translation>
    </message>
    <message>
        <source>%2 %1 is not finite</source>
        <translation>%2 %1 n&apos;est pas fini</translation>
    </message>
    <message>
        <source>%2 %1 %3</source>
        <translation>%2 %1 %3</translation>
    </message>
    <message>
        <source>%2 %1 is not an integer</source>
        <translation>%2 %1 n&apos;est pas un entier</translation>
    </message>
    <message>
        <source>x coordinate</source>
        <translation>coordonnée x</translation>
    </message>
    <message>
        <source>y coordinate</source>
        <translation>coordonnée y</translation>
    </message>
    <message>
        <source>z coordinate</source>
        <translation>coordonnée z</translation>
    </message>
    <message>
        <source>TFACE id</source>
        <translation>identifiant TFACE</translation>
    </message>
    <message>
        <source>BSTONE vertex id</source>
        <translation>identifiant de sommet BSTONE</translation>
    </message>
    <message>
        <source>BORDER id</source>
        <translation>identifiant BORDER</translation>
    </message>
    <message>
        <source>BORDER corner vertex id</source>
        <translation>identifiant du sommet de coin BORDER</translation>
    </message>
    <message>
        <source>BORDER next vertex id</source>
        <translation>identifiant du sommet suivant BORDER</translation>
    </message>
    <message>
        <source>vertex id</source>
        <translation>identifiant de sommet</translation>
    </message>
    <message>
        <source>referenced vertex id</source>
        <translation>identifiant du sommet référencé</translation>
    </message>
    <message>
        <source>TRGL vertex id</source>
        <translation>identifiant de sommet TRGL</translation>
    </message>
    <message>
        <source>cannot replace the file: %1 (no output was written)</source>
        <translation>impossible de remplacer le fichier : %1 (aucune sortie n&apos;a été écrite)</translation>
    </message>
    <message>
        <source>an entity count</source>
        <translation>un nombre d&apos;entités</translation>
    </message>
    <message>
        <source>an entity id</source>
        <translation>un identifiant d&apos;entité</translation>
    </message>
    <message>
        <source>a boundary id</source>
        <translation>un identifiant de bord</translation>
    </message>
    <message>
        <source>a geological entity id</source>
        <translation>un identifiant d&apos;entité géologique</translation>
    </message>
    <message>
        <source>a child id</source>
        <translation>un identifiant d&apos;enfant</translation>
    </message>
    <message>
        <source>vertex %1 (numbered from 0): %2</source>
        <translation>sommet %1 (numéroté à partir de 0) : %2</translation>
    </message>
    <message>
        <source>vertex %1 (numbered from 0, as faces index it): %2</source>
        <translation>sommet %1 (numéroté à partir de 0, comme les faces l&apos;indexent) : %2</translation>
    </message>
    <message>
        <source>facet %1: %2</source>
        <translation>facette %1 : %2</translation>
    </message>
    <message>
        <source>coordinate &apos;%1&apos; %2</source>
        <translation>la coordonnée &apos;%1&apos; %2</translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation>%1 %2 : %3</translation>
    </message>
    <message>
        <source>cell %1 (numbered from 0, VTK type %2) has %3 point ids, its type needs %4</source>
        <translation>la cellule %1 (numérotée à partir de 0, type VTK %2) a %3 identifiants de points, son type en demande %4</translation>
    </message>
    <message>
        <source>cell %1 (numbered from 0, VTK type %2) has %3 point ids</source>
        <translation>la cellule %1 (numérotée à partir de 0, type VTK %2) a %3 identifiants de points</translation>
    </message>
    <message>
        <source>cell %1 has VTK type %2, which StrataMesh does not exchange (tets, pyramids, wedges, triangles, lines and vertices only)</source>
        <translation>la cellule %1 est de type VTK %2, que StrataMesh n&apos;échange pas (tétraèdres, pyramides, prismes, triangles, lignes et sommets seulement)</translation>
    </message>
    <message>
        <source>cell %1 uses point %2 of %3</source>
        <translation>la cellule %1 utilise le point %2 sur %3</translation>
    </message>
    <message>
        <source>is not a number</source>
        <translation>n&apos;est pas un nombre</translation>
    </message>
    <message>
        <source>is not a whole number from 0 to 18446744073709551615</source>
        <translation>n&apos;est pas un entier de 0 à 18446744073709551615</translation>
    </message>
    <message>
        <source>is not an integer</source>
        <translation>n&apos;est pas un entier</translation>
    </message>
    <message>
        <source>is out of range for %1</source>
        <translation>est hors des limites de %1</translation>
    </message>
    <message>
        <source>%1 data is cut short: %2 bits, %3 bytes are left</source>
        <translation>les données de %1 sont tronquées : %2 bits, il reste %3 octets</translation>
    </message>
    <message>
        <source>%1 data is cut short: %2 values of %3 bytes, %4 bytes are left</source>
        <translation>les données de %1 sont tronquées : %2 valeurs de %3 octets, il reste %4 octets</translation>
    </message>
    <message>
        <source>%1 value &apos;%2&apos; %3</source>
        <translation>%1 : la valeur &apos;%2&apos; %3</translation>
    </message>
    <message>
        <source>is out of range for a 4-byte integer</source>
        <translation>dépasse les limites d&apos;un entier de 4 octets</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a keyword of %2 (%3)</source>
        <translation>&quot;%1&quot; n&apos;est pas un mot-clé de %2 (%3)</translation>
    </message>
    <message>
        <source>%1 declares %2 values, the cell section is missing: the file has no cells</source>
        <translation>%1 déclare %2 valeurs, la section des cellules manque : le fichier n&apos;a pas de cellules</translation>
    </message>
    <message>
        <source>%1 declares %2 values, the cell section at line %3 declares %4</source>
        <translation>%1 déclare %2 valeurs, la section des cellules à la ligne %3 en déclare %4</translation>
    </message>
    <message>
        <source>%1 declares %2 values, POINTS at line %3 declares %4</source>
        <translation>%1 déclare %2 valeurs, POINTS à la ligne %3 en déclare %4</translation>
    </message>
</context>
<context>
    <name>stratamesh::ExaggerationWorkflow</name>
    <message>
        <source>Vertical E&amp;xaggeration</source>
        <translation>E&amp;xagération verticale</translation>
    </message>
    <message>
        <source>Stretch the vertical axis of both views, to see thin layers and low dips</source>
        <translation>Étirer l’axe vertical des deux vues, pour voir les couches minces et les faibles pendages</translation>
    </message>
    <message>
        <source>%1 (true scale)</source>
        <translation>%1 (échelle réelle)</translation>
    </message>
    <message>
        <source>Vertical exaggeration %1</source>
        <translation>Exagération verticale %1</translation>
    </message>
    <message>
        <source>Vertical exaggeration off: true scale</source>
        <translation>Exagération verticale désactivée : échelle réelle</translation>
    </message>
    <message>
        <source>Vertical exaggeration %1: the views are not to scale</source>
        <translation>Exagération verticale %1 : les vues ne sont pas à l’échelle</translation>
    </message>
    <message>
        <source>Vertical Exaggeration</source>
        <translation>Exagération verticale</translation>
    </message>
    <message>
        <source>Vertical axis stretched by (%1 to %2):</source>
        <translation>Axe vertical étiré de (%1 à %2) :</translation>
    </message>
    <message>
        <source>&amp;Other…</source>
        <translation>&amp;Autre…</translation>
    </message>
    <message>
        <source>&amp;Other (%1)…</source>
        <translation>&amp;Autre (%1)…</translation>
    </message>
</context>
<context>
    <name>stratamesh::ExportController</name>
    <message>
        <source>Exporting</source>
        <translation>Export en cours</translation>
    </message>
    <message>
        <source>The export stopped without a result</source>
        <translation>L&apos;export s&apos;est arrêté sans résultat</translation>
    </message>
</context>
<context>
    <name>stratamesh::ExportDialog</name>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>%1 (*%2)</source>
        <translation>%1 (*%2)</translation>
    </message>
    <message>
        <source>4.1 (Gmsh 4)</source>
        <translation>4.1 (Gmsh 4)</translation>
    </message>
    <message>
        <source>2.2 (older readers)</source>
        <translation>2.2 (lecteurs plus anciens)</translation>
    </message>
    <message>
        <source>Keep elements without a group (Gmsh Mesh.SaveAll)</source>
        <translation>Garder les éléments sans groupe (Gmsh Mesh.SaveAll)</translation>
    </message>
    <message>
        <source>Gmsh keeps only elements of a physical group; this writes the others too, in an entity without one</source>
        <translation>Gmsh ne garde que les éléments d&apos;un groupe physique ; ceci écrit aussi les autres, dans une entité sans groupe</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Parcourir…</translation>
    </message>
    <message>
        <source>&amp;Export:</source>
        <translation>&amp;Exporter :</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>&amp;Format :</translation>
    </message>
    <message>
        <source>MSH &amp;version:</source>
        <translation>&amp;Version MSH :</translation>
    </message>
    <message>
        <source>&amp;Surface:</source>
        <translation>&amp;Surface :</translation>
    </message>
    <message>
        <source>F&amp;ile:</source>
        <translation>F&amp;ichier :</translation>
    </message>
    <message>
        <source>E&amp;xport</source>
        <translation>E&amp;xporter</translation>
    </message>
    <message>
        <source>This format holds tetrahedra; a surface model has none</source>
        <translation>Ce format contient des tétraèdres ; un modèle surfacique n&apos;en a pas</translation>
    </message>
    <message>
        <source>This format holds no volume cells</source>
        <translation>Ce format ne contient pas de cellules volumiques</translation>
    </message>
    <message>
        <source>This format holds tetrahedra only; this mesh has pyramids and prisms</source>
        <translation>Ce format ne contient que des tétraèdres ; ce maillage a des pyramides et des prismes</translation>
    </message>
    <message>
        <source>every surface but the chosen one</source>
        <translation>toutes les surfaces sauf celle choisie</translation>
    </message>
    <message>
        <source>surface names</source>
        <translation>les noms des surfaces</translation>
    </message>
    <message>
        <source>feature types (horizon, fault…)</source>
        <translation>les types d&apos;objets géologiques (horizon, faille…)</translation>
    </message>
    <message>
        <source>regions</source>
        <translation>les régions</translation>
    </message>
    <message>
        <source>contact lines and corners</source>
        <translation>les lignes de contact et les coins</translation>
    </message>
    <message>
        <source>volume cells</source>
        <translation>les cellules volumiques</translation>
    </message>
    <message>
        <source>pyramids and prisms</source>
        <translation>les pyramides et les prismes</translation>
    </message>
    <message>
        <source>double precision (coordinates stored as 32-bit floats)</source>
        <translation>la double précision (coordonnées stockées en flottants 32 bits)</translation>
    </message>
    <message>
        <source>%1 does not keep: %2.</source>
        <translation>%1 ne conserve pas : %2.</translation>
    </message>
    <message>
        <source>All surfaces</source>
        <translation>Toutes les surfaces</translation>
    </message>
    <message>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Export To</source>
        <translation>Exporter vers</translation>
    </message>
    <message>
        <source>Nothing can be exported yet: open a model first.</source>
        <translation>Rien ne peut encore être exporté : ouvrez d&apos;abord un modèle.</translation>
    </message>
</context>
<context>
    <name>stratamesh::ExportWorkflow</name>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exporter…</translation>
    </message>
    <message>
        <source>Write the model, its remesh or a volume mesh to another file format</source>
        <translation>Écrire le modèle, son remaillage ou un maillage volumique dans un autre format de fichier</translation>
    </message>
    <message>
        <source>Input model</source>
        <translation>Modèle d&apos;entrée</translation>
    </message>
    <message>
        <source>No model is open</source>
        <translation>Aucun modèle n&apos;est ouvert</translation>
    </message>
    <message>
        <source>Remeshed model</source>
        <translation>Modèle remaillé</translation>
    </message>
    <message>
        <source>No remeshed model: run Mesh &gt; Remesh… first</source>
        <translation>Pas de modèle remaillé : lancez d&apos;abord Maillage &gt; Remailler…</translation>
    </message>
    <message>
        <source>No TetGen mesh: run Mesh &gt; Tetrahedralise… first</source>
        <translation>Pas de maillage TetGen : lancez d&apos;abord Maillage &gt; Tétraédriser…</translation>
    </message>
    <message>
        <source>The last tetrahedralisation did not mesh the remeshed model</source>
        <translation>La dernière tétraédrisation n&apos;a pas maillé le modèle remaillé</translation>
    </message>
    <message>
        <source>TetGen mesh of the input</source>
        <translation>Maillage TetGen de l&apos;entrée</translation>
    </message>
    <message>
        <source>TetGen failed on the input model</source>
        <translation>TetGen a échoué sur le modèle d&apos;entrée</translation>
    </message>
    <message>
        <source>TetGen mesh of the remesh</source>
        <translation>Maillage TetGen du remaillage</translation>
    </message>
    <message>
        <source>TetGen failed on the remeshed model</source>
        <translation>TetGen a échoué sur le modèle remaillé</translation>
    </message>
    <message>
        <source>Hybrid mesh</source>
        <translation>Maillage hybride</translation>
    </message>
    <message>
        <source>No hybrid mesh: run Mesh &gt; Hybrid Mesh… first</source>
        <translation>Pas de maillage hybride : lancez d&apos;abord Maillage &gt; Maillage hybride…</translation>
    </message>
    <message>
        <source>cannot tell the format from the extension (use %1)</source>
        <translation>impossible de déduire le format de l&apos;extension (utilisez %1)</translation>
    </message>
    <message>
        <source>another run is under way</source>
        <translation>un autre calcul est en cours</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>Export de %1…</translation>
    </message>
    <message>
        <source>Exported as %1 in %2 s</source>
        <translation>Exporté au format %1 en %2 s</translation>
    </message>
    <message>
        <source>%1 elements without a region, surface or line were left out, as Gmsh does; “Keep elements without a group” keeps them</source>
        <translation>%1 éléments sans région, surface ni ligne ont été omis, comme le fait Gmsh ; « Garder les éléments sans groupe » les conserve</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exporté</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>Échec de l&apos;export : %1</translation>
    </message>
    <message>
        <source>Could not export</source>
        <translation>Impossible d&apos;exporter</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
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
    <name>stratamesh::HistogramChart</name>
    <message>
        <source>Input</source>
        <translation>Entrée</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Sortie</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln triangle(s), %2 %</source>
        <translation>
            <numerusform>%1 : %Ln triangle, %2 %</numerusform>
            <numerusform>%1 : %Ln triangles, %2 %</numerusform>
        </translation>
    </message>
    <message>
        <source>[%1, %2)</source>
        <translation>[%1 ; %2[</translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridController</name>
    <message>
        <source>Building the hybrid mesh</source>
        <translation>Construction du maillage hybride</translation>
    </message>
    <message>
        <source>The hybrid mesher stopped without a result</source>
        <translation>Le mailleur hybride s&apos;est arrêté sans résultat</translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridDialog</name>
    <message>
        <source>Hybrid Mesh</source>
        <translation>Maillage hybride</translation>
    </message>
    <message>
        <source>&amp;Build Mesh</source>
        <translation>&amp;Construire le maillage</translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridPanel</name>
    <message>
        <source>C&amp;olour cells by:</source>
        <translation>C&amp;olorer les cellules par :</translation>
    </message>
    <message>
        <source>Cell type</source>
        <translation>Type de cellule</translation>
    </message>
    <message>
        <source>Min dihedral angle</source>
        <translation>Angle dièdre minimal</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Région</translation>
    </message>
    <message>
        <source>Tetrahedra</source>
        <translation>Tétraèdres</translation>
    </message>
    <message>
        <source>Pyramids</source>
        <translation>Pyramides</translation>
    </message>
    <message>
        <source>Prisms</source>
        <translation>Prismes</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Cellules</translation>
    </message>
    <message>
        <source>Min dihedral (°)</source>
        <translation>Dièdre min. (°)</translation>
    </message>
    <message>
        <source>Max dihedral (°)</source>
        <translation>Dièdre max. (°)</translation>
    </message>
    <message>
        <source>Slivers</source>
        <translation>Tétraèdres plats</translation>
    </message>
    <message>
        <source>Tetrahedra with a dihedral angle below 5° or above 175°</source>
        <translation>Tétraèdres ayant un angle dièdre inférieur à 5° ou supérieur à 175°</translation>
    </message>
    <message>
        <source>Valid mixed mesh</source>
        <translation>Maillage mixte valide</translation>
    </message>
    <message>
        <source>Not valid: %1</source>
        <translation>Non valide : %1</translation>
    </message>
    <message>
        <source>Invalid cells found: %1  ·  repaired: %2</source>
        <translation>Cellules invalides trouvées : %1  ·  réparées : %2</translation>
    </message>
    <message>
        <source>No hybrid cell could be kept: this is TetGen&apos;s mesh of the remesh</source>
        <translation>Aucune cellule hybride n&apos;a pu être conservée : c&apos;est le maillage TetGen du remaillage</translation>
    </message>
    <message>
        <source>Time: %1 s</source>
        <translation>Durée : %1 s</translation>
    </message>
    <message>
        <source>Mean min dihedral (°)</source>
        <translation>Dièdre min. moyen (°)</translation>
    </message>
    <message>
        <source>Mean over the cells of each cell&apos;s smallest dihedral angle</source>
        <translation>Moyenne sur les cellules du plus petit angle dièdre de chacune</translation>
    </message>
    <message>
        <source>Cells between two surfaces: %1  ·  at Voronoi vertices: %2  ·  transition pyramids: %3  ·  TetGen&apos;s tets: %4</source>
        <translation>Cellules entre deux surfaces : %1  ·  aux sommets de Voronoï : %2  ·  pyramides de transition : %3  ·  tétraèdres de TetGen : %4</translation>
    </message>
</context>
<context>
    <name>stratamesh::HybridWorkflow</name>
    <message>
        <source>&amp;Hybrid Mesh…</source>
        <translation>Maillage &amp;hybride…</translation>
    </message>
    <message>
        <source>Mesh the regions with prisms in the thin layers, tetrahedra elsewhere and pyramids between them</source>
        <translation>Mailler les régions avec des prismes dans les couches minces, des tétraèdres ailleurs et des pyramides entre les deux</translation>
    </message>
    <message>
        <source>Cancel &amp;Hybrid Mesh</source>
        <translation>Annuler le maillage &amp;hybride</translation>
    </message>
    <message>
        <source>Stop the hybrid mesher; the previous hybrid mesh is kept</source>
        <translation>Arrêter le mailleur hybride ; le maillage hybride précédent est conservé</translation>
    </message>
    <message>
        <source>Save &amp;Hybrid Mesh As…</source>
        <translation>Enregistrer le maillage &amp;hybride sous…</translation>
    </message>
    <message>
        <source>Write the hybrid mesh as a VTK (.vtu) or Gmsh (.msh) file</source>
        <translation>Écrire le maillage hybride dans un fichier VTK (.vtu) ou Gmsh (.msh)</translation>
    </message>
    <message>
        <source>Hybrid Mesh</source>
        <translation>Maillage hybride</translation>
    </message>
    <message>
        <source>&amp;Hybrid Mesh</source>
        <translation>Maillage &amp;hybride</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Région</translation>
    </message>
    <message>
        <source>Min dihedral
angle (°)</source>
        <translation>Angle dièdre
min. (°)</translation>
    </message>
    <message>
        <source>tetrahedron</source>
        <translation>tétraèdre</translation>
    </message>
    <message>
        <source>pyramid</source>
        <translation>pyramide</translation>
    </message>
    <message>
        <source>prism</source>
        <translation>prisme</translation>
    </message>
    <message>
        <source>Cell type</source>
        <translation>Type de cellule</translation>
    </message>
    <message>
        <source>Building the hybrid mesh of %1…</source>
        <translation>Construction du maillage hybride de %1…</translation>
    </message>
    <message>
        <source>Hybrid mesh: %1 tetrahedra, %2 pyramids, %3 prisms, %4 in %5 s</source>
        <translation>Maillage hybride : %1 tétraèdres, %2 pyramides, %3 prismes, %4 en %5 s</translation>
    </message>
    <message>
        <source>valid</source>
        <translation>valide</translation>
    </message>
    <message>
        <source>not valid (%1)</source>
        <translation>non valide (%1)</translation>
    </message>
    <message>
        <source>Hybrid mesh built — see Hybrid Mesh</source>
        <translation>Maillage hybride construit — voir Maillage hybride</translation>
    </message>
    <message>
        <source>The hybrid mesh is not valid — see Messages</source>
        <translation>Le maillage hybride n&apos;est pas valide — voir Messages</translation>
    </message>
    <message>
        <source>Hybrid meshing failed: %1</source>
        <translation>Échec du maillage hybride : %1</translation>
    </message>
    <message>
        <source>Hybrid meshing failed — see Messages</source>
        <translation>Échec du maillage hybride — voir Messages</translation>
    </message>
    <message>
        <source>Hybrid meshing cancelled; the previous mesh is kept</source>
        <translation>Maillage hybride annulé ; le maillage précédent est conservé</translation>
    </message>
    <message>
        <source>Hybrid meshing cancelled</source>
        <translation>Maillage hybride annulé</translation>
    </message>
    <message>
        <source>Input: %1</source>
        <translation>Entrée : %1</translation>
    </message>
    <message>
        <source>Hybrid mesh: %1 cells, %2 sites</source>
        <translation>Maillage hybride : %1 cellules, %2 sites</translation>
    </message>
    <message>
        <source>VTK unstructured grid (*.vtu)</source>
        <translation>Grille non structurée VTK (*.vtu)</translation>
    </message>
    <message>
        <source>Gmsh mesh (*.msh)</source>
        <translation>Maillage Gmsh (*.msh)</translation>
    </message>
    <message>
        <source>Save Hybrid Mesh</source>
        <translation>Enregistrer le maillage hybride</translation>
    </message>
    <message>
        <source>a hybrid mesh is saved as a .vtu or .msh file</source>
        <translation>un maillage hybride s&apos;enregistre en fichier .vtu ou .msh</translation>
    </message>
    <message>
        <source>Hybrid mesh saved</source>
        <translation>Maillage hybride enregistré</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Could not save the hybrid mesh</source>
        <translation>Impossible d&apos;enregistrer le maillage hybride</translation>
    </message>
    <message>
        <source>Hybrid meshing cancelled: no mesh</source>
        <translation>Maillage hybride annulé : aucun maillage</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
    </message>
    <message>
        <source>no hybrid mesh is being built</source>
        <translation>aucun maillage hybride n&apos;est en construction</translation>
    </message>
    <message>
        <source>no hybrid mesh yet</source>
        <translation>pas encore de maillage hybride</translation>
    </message>
</context>
<context>
    <name>stratamesh::LedgerPanel</name>
    <message>
        <source>No simplification</source>
        <translation>Aucune simplification</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation>Type :</translation>
    </message>
    <message>
        <source>All kinds</source>
        <translation>Tous les types</translation>
    </message>
    <message>
        <source>Search…</source>
        <translation>Rechercher…</translation>
    </message>
    <message>
        <source>Show only the records whose text holds this (any column)</source>
        <translation>N’afficher que les enregistrements dont le texte contient ceci (dans toute colonne)</translation>
    </message>
</context>
<context>
    <name>stratamesh::LedgerTableModel</name>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Input entities</source>
        <translation>Entités d&apos;entrée</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Sortie</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Remarque</translation>
    </message>
    <message>
        <source>Corner merge</source>
        <translation>Fusion de coins</translation>
    </message>
    <message>
        <source>Multi-point merge</source>
        <translation>Fusion multipoint</translation>
    </message>
    <message>
        <source>Close feature merge</source>
        <translation>Fusion d&apos;éléments proches</translation>
    </message>
    <message>
        <source>Degenerate contact triangle</source>
        <translation>Triangle dégénéré au contact</translation>
    </message>
    <message>
        <source>Degenerate border triangle</source>
        <translation>Triangle dégénéré au bord</translation>
    </message>
    <message>
        <source>Valence-3 vertex removed</source>
        <translation>Sommet de valence 3 supprimé</translation>
    </message>
    <message>
        <source>Surface lost</source>
        <translation>Surface perdue</translation>
    </message>
    <message>
        <source>Line lost</source>
        <translation>Ligne perdue</translation>
    </message>
    <message>
        <source>Corner lost</source>
        <translation>Coin perdu</translation>
    </message>
    <message>
        <source>Surface created</source>
        <translation>Surface créée</translation>
    </message>
    <message>
        <source>Line created</source>
        <translation>Ligne créée</translation>
    </message>
    <message>
        <source>Corner created</source>
        <translation>Coin créé</translation>
    </message>
    <message>
        <source>Unresolved intersection</source>
        <translation>Intersection non résolue</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>sommet %1</translation>
    </message>
    <message>
        <source>%1 (distance)</source>
        <translation>%1 (distance)</translation>
    </message>
    <message>
        <source>%1 (area)</source>
        <translation>%1 (aire)</translation>
    </message>
    <message>
        <source>%1 (length)</source>
        <translation>%1 (longueur)</translation>
    </message>
    <message>
        <source>Surface part lost</source>
        <translation>Partie de surface perdue</translation>
    </message>
    <message>
        <source>Surface part created</source>
        <translation>Partie de surface créée</translation>
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
    <message>
        <source>&amp;Mesh</source>
        <translation>&amp;Maillage</translation>
    </message>
    <message>
        <source>&amp;Analyse</source>
        <translation>A&amp;nalyse</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>StrataMesh[*]</source>
        <translation>StrataMesh[*]</translation>
    </message>
    <message>
        <source>%1[*] — StrataMesh</source>
        <translation>%1[*] — StrataMesh</translation>
    </message>
    <message>
        <source>%1 (%2)[*] — StrataMesh</source>
        <translation>%1 (%2)[*] — StrataMesh</translation>
    </message>
    <message>
        <source>&amp;Link Cameras</source>
        <translation>&amp;Lier les caméras</translation>
    </message>
    <message>
        <source>Move the input and output views together; unchecked, each view has its own camera</source>
        <translation>Déplacer ensemble les vues d’entrée et de sortie ; décoché, chaque vue a sa propre caméra</translation>
    </message>
    <message>
        <source>nothing to undo</source>
        <translation>rien à annuler</translation>
    </message>
    <message>
        <source>nothing to redo</source>
        <translation>rien à rétablir</translation>
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
    <message>
        <source>%1
Click to show it in the views</source>
        <translation>%1
Cliquer pour le montrer dans les vues</translation>
    </message>
</context>
<context>
    <name>stratamesh::ModelTreeModel</name>
    <message>
        <source>horizon</source>
        <translation>horizon</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>faille</translation>
    </message>
    <message>
        <source>unconformity</source>
        <translation>discordance</translation>
    </message>
    <message>
        <source>box</source>
        <translation>boîte</translation>
    </message>
    <message>
        <source>other</source>
        <translation>autre</translation>
    </message>
    <message>
        <source>Regions</source>
        <translation>Régions</translation>
    </message>
    <message>
        <source>Surfaces (%1)</source>
        <translation>Surfaces (%1)</translation>
    </message>
    <message>
        <source>Horizons (%1)</source>
        <translation>Horizons (%1)</translation>
    </message>
    <message>
        <source>Faults (%1)</source>
        <translation>Failles (%1)</translation>
    </message>
    <message>
        <source>Unconformities (%1)</source>
        <translation>Discordances (%1)</translation>
    </message>
    <message>
        <source>Other Surfaces (%1)</source>
        <translation>Autres surfaces (%1)</translation>
    </message>
    <message>
        <source>Box (%1)</source>
        <translation>Boîte (%1)</translation>
    </message>
    <message>
        <source>Lines</source>
        <translation>Lignes</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Coins</translation>
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
            <numerusform>Ligne %1 — longueur %2, %n surface</numerusform>
            <numerusform>Ligne %1 — longueur %2, %n surfaces</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Corner %1 at (%2, %3, %4) — %n line(s)</source>
        <translation>
            <numerusform>Coin %1 en (%2, %3, %4) — %n ligne</numerusform>
            <numerusform>Coin %1 en (%2, %3, %4) — %n lignes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Region %1 — %n boundary surface(s)</source>
        <translation>
            <numerusform>Région %1 — %n surface limite</numerusform>
            <numerusform>Région %1 — %n surfaces limites</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stratamesh::ModelTreePanel</name>
    <message>
        <source>Lines</source>
        <translation>Lignes</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Coins</translation>
    </message>
    <message>
        <source>Filter by name</source>
        <translation>Filtrer par nom</translation>
    </message>
    <message>
        <source>Show box</source>
        <translation>Afficher la boîte</translation>
    </message>
    <message>
        <source>Show the surfaces of the model&apos;s bounding box</source>
        <translation>Afficher les surfaces de la boîte englobante du modèle</translation>
    </message>
</context>
<context>
    <name>stratamesh::ModelTreeWorkflow</name>
    <message>
        <source>Model</source>
        <translation>Modèle</translation>
    </message>
    <message>
        <source>Model &amp;Tree</source>
        <translation>&amp;Arbre du modèle</translation>
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
        <translation>Afficher %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Masquer %1</translation>
    </message>
    <message>
        <source>Output surface %1, triangle %2: min angle %3°, Q = %4</source>
        <translation>Surface de sortie %1, triangle %2 : angle min. %3°, Q = %4</translation>
    </message>
    <message>
        <source>Surface %1, triangle %2: min angle %3°, Q = %4</source>
        <translation>Surface %1, triangle %2 : angle min. %3°, Q = %4</translation>
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
        <source>Loading stopped without a result</source>
        <translation>Le chargement s&apos;est arrêté sans résultat</translation>
    </message>
    <message>
        <source>Sample model</source>
        <translation>Modèle d&apos;exemple</translation>
    </message>
    <message>
        <source>Structural models</source>
        <translation>Modèles structuraux</translation>
    </message>
    <message>
        <source>All files</source>
        <translation>Tous les fichiers</translation>
    </message>
</context>
<context>
    <name>stratamesh::OpenWorkflow</name>
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
        <source>Open Model</source>
        <translation>Ouvrir un modèle</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>Ouverture de %1…</translation>
    </message>
    <message>
        <source>%1 opened in %2 s</source>
        <translation>%1 ouvert en %2 s</translation>
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
</context>
<context>
    <name>stratamesh::ParamForm</name>
    <message>
        <source>(thesis %1)</source>
        <translation>(thèse, %1)</translation>
    </message>
</context>
<context>
    <name>stratamesh::Params</name>
    <message>
        <source>Characteristic size &amp;h:</source>
        <translation>Taille caractéristique &amp;h :</translation>
    </message>
    <message>
        <source>Elements smaller than h (h² for surfaces, h³ for regions) are complex.</source>
        <translation>Les éléments plus petits que h (h² pour les surfaces, h³ pour les régions) sont complexes.</translation>
    </message>
    <message>
        <source>&amp;Angle α:</source>
        <translation>&amp;Angle α :</translation>
    </message>
    <message>
        <source>Angles between elements smaller than α are complex.</source>
        <translation>Les angles entre éléments inférieurs à α sont complexes.</translation>
    </message>
    <message>
        <source>Number of &amp;cells:</source>
        <translation>Nombre de &amp;cellules :</translation>
    </message>
    <message>
        <source>Cells of the volumetric Voronoi diagram in which model elements are counted (the thesis uses 100, 1000 and 10000).</source>
        <translation>Cellules du diagramme de Voronoï volumique dans lesquelles les éléments du modèle sont comptés (la thèse utilise 100, 1000 et 10000).</translation>
    </message>
    <message>
        <source>Ra&amp;ndom seed:</source>
        <translation>&amp;Graine aléatoire :</translation>
    </message>
    <message>
        <source>Seed of the initial random sites: the same seed gives the same cells.</source>
        <translation>Graine des sites aléatoires initiaux : la même graine donne les mêmes cellules.</translation>
    </message>
    <message>
        <source>&amp;Lloyd iterations:</source>
        <translation>Itérations de &amp;Lloyd :</translation>
    </message>
    <message>
        <source>Lloyd iterations of the volumetric centroidal Voronoi tessellation.</source>
        <translation>Itérations de Lloyd de la tessellation de Voronoï centroïdale volumique.</translation>
    </message>
    <message>
        <source>&amp;Iterations:</source>
        <translation>&amp;Itérations :</translation>
    </message>
    <message>
        <source>Iterations of the centroidal Voronoi optimisation of the sites.</source>
        <translation>Itérations de l&apos;optimisation de Voronoï centroïdale des sites.</translation>
    </message>
    <message>
        <source>Boundary &amp;weight α:</source>
        <translation>&amp;Poids du bord α :</translation>
    </message>
    <message>
        <source>Weight of the boundary energy in F = (1 − α) F_CVT + α F_B.</source>
        <translation>Poids de l&apos;énergie de bord dans F = (1 − α) F_CVT + α F_B.</translation>
    </message>
    <message>
        <source>&amp;Lloyd iterations</source>
        <translation>Itérations de &amp;Lloyd</translation>
    </message>
    <message>
        <source>Lloyd iterations instead of L-BFGS (the CVT energy alone: no boundary weight).</source>
        <translation>Itérations de Lloyd au lieu de L-BFGS (l&apos;énergie CVT seule : pas de poids du bord).</translation>
    </message>
    <message>
        <source>Number of &amp;sites:</source>
        <translation>Nombre de &amp;sites :</translation>
    </message>
    <message>
        <source>Sites spread over all the surfaces; each becomes about one vertex. At least one per surface; 0: from the edge length.</source>
        <translation>Sites répartis sur toutes les surfaces ; chacun devient à peu près un sommet. Au moins un par surface ; 0 : d&apos;après la longueur d&apos;arête.</translation>
    </message>
    <message>
        <source>Target &amp;edge length:</source>
        <translation>&amp;Longueur d&apos;arête visée :</translation>
    </message>
    <message>
        <source>The number of sites is derived from the total area for this edge length (hexagonal packing); 0: from the number of sites.</source>
        <translation>Le nombre de sites est déduit de l&apos;aire totale pour cette longueur d&apos;arête (empilement hexagonal) ; 0 : d&apos;après le nombre de sites.</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Désactivé</translation>
    </message>
    <message>
        <source>&amp;d_resolution:</source>
        <translation>&amp;d_resolution :</translation>
    </message>
    <message>
        <source>× edge length</source>
        <translation>× longueur d&apos;arête</translation>
    </message>
    <message>
        <source>Remove thin s&amp;trips under:</source>
        <translation>Supprimer les &amp;bandes fines sous :</translation>
    </message>
    <message>
        <source>Surfaces narrower than this between two long lines (a small fault throw) are removed whole before remeshing, their two lines merged into one; 0 keeps them.</source>
        <translation>Les surfaces plus étroites que cela entre deux longues lignes (un petit rejet de faille) sont supprimées entières avant le remaillage, leurs deux lignes fusionnées en une seule ; 0 les garde.</translation>
    </message>
    <message>
        <source>Seed of the initial random sampling: the same seed gives the same mesh.</source>
        <translation>Graine de l&apos;échantillonnage aléatoire initial : la même graine donne le même maillage.</translation>
    </message>
    <message>
        <source>Re&amp;finement rounds:</source>
        <translation>&amp;Tours de raffinement :</translation>
    </message>
    <message>
        <source>Rounds of more sites where the result is not valid or its topology differs from the input&apos;s (4 more while it is not valid); 0 turns refinement off.</source>
        <translation>Tours de sites supplémentaires là où le résultat n&apos;est pas valide ou que sa topologie diffère de celle de l&apos;entrée (4 de plus tant qu&apos;il n&apos;est pas valide) ; 0 désactive le raffinement.</translation>
    </message>
    <message>
        <source>&amp;Adaptive density (more sites near corners)</source>
        <translation>Densité &amp;adaptative (plus de sites près des coins)</translation>
    </message>
    <message>
        <source>Site density grows near corners, so small features keep more triangles.</source>
        <translation>La densité de sites croît près des coins, les petits éléments gardent ainsi plus de triangles.</translation>
    </message>
    <message>
        <source>&amp;Merge all extra points of a cell</source>
        <translation>&amp;Fusionner tous les points en trop d&apos;une cellule</translation>
    </message>
    <message>
        <source>A cell part with more than two points has them all merged, as in the thesis; without it, only the closest until two are left, which keeps more of the model.</source>
        <translation>Une partie de cellule de plus de deux points les voit tous fusionnés, comme dans la thèse ; sans cela, seulement les plus proches jusqu&apos;à ce qu&apos;il en reste deux, ce qui garde davantage du modèle.</translation>
    </message>
    <message>
        <source>&amp;Quality (radius-edge ratio):</source>
        <translation>&amp;Qualité (rapport rayon/arête) :</translation>
    </message>
    <message>
        <source>Largest circumradius to shortest edge ratio TetGen accepts (its q switch); 0 turns quality refinement off.</source>
        <translation>Plus grand rapport du rayon circonscrit à l&apos;arête la plus courte accepté par TetGen (son option q) ; 0 désactive le raffinement de qualité.</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Aucun</translation>
    </message>
    <message>
        <source>&amp;Maximum tet volume:</source>
        <translation>Volume &amp;maximal d&apos;un tétraèdre :</translation>
    </message>
    <message>
        <source>Largest volume of a tetrahedron (TetGen&apos;s a switch); 0 sets none.</source>
        <translation>Plus grand volume d&apos;un tétraèdre (option a de TetGen) ; 0 n&apos;en impose aucun.</translation>
    </message>
    <message>
        <source>&amp;Time limit per model:</source>
        <translation>&amp;Temps limite par modèle :</translation>
    </message>
    <message>
        <source>TetGen is stopped after this time on each model; a raw input model can keep it busy for hours. 0 sets none.</source>
        <translation>TetGen est arrêté après ce temps sur chaque modèle ; un modèle d&apos;entrée brut peut l&apos;occuper des heures. 0 n&apos;en impose aucun.</translation>
    </message>
    <message>
        <source>Memory &amp;limit per model:</source>
        <translation>&amp;Limite de mémoire par modèle :</translation>
    </message>
    <message>
        <source>Address space the TetGen helper may use; 0 sets none.</source>
        <translation>Espace d&apos;adressage que le processus auxiliaire de TetGen peut utiliser ; 0 n&apos;en impose aucun.</translation>
    </message>
    <message>
        <source>Let TetGen &amp;refine the surfaces</source>
        <translation>Laisser TetGen &amp;raffiner les surfaces</translation>
    </message>
    <message>
        <source>Without it every surface triangle is kept as it is (TetGen&apos;s Y switch), so the meshes show what the surfaces themselves give.</source>
        <translation>Sans cela, chaque triangle des surfaces est gardé tel quel (option Y de TetGen) : les maillages montrent ce que donnent les surfaces elles-mêmes.</translation>
    </message>
    <message>
        <source>&amp;Keep nearly coplanar triangles apart</source>
        <translation>&amp;Garder séparés les triangles presque coplanaires</translation>
    </message>
    <message>
        <source>When TetGen refines the surfaces it merges nearly coplanar triangles, which moves region volumes by about 1e-6; this keeps them exact (its M switch) but refines much more.</source>
        <translation>Quand TetGen raffine les surfaces, il fusionne les triangles presque coplanaires, ce qui change les volumes des régions d&apos;environ 1e-6 ; cette option les garde exacts (son option M) mais raffine bien plus.</translation>
    </message>
    <message>
        <source>Number of volume &amp;sites:</source>
        <translation>Nombre de &amp;sites volumiques :</translation>
    </message>
    <message>
        <source>Sites of the volumetric centroidal Voronoi diagram of the model&apos;s box; the surfaces are remeshed from them.</source>
        <translation>Sites du diagramme de Voronoï centroïdal volumique de la boîte du modèle ; les surfaces sont remaillées à partir d&apos;eux.</translation>
    </message>
    <message>
        <source>&amp;Thin-layer ratio:</source>
        <translation>Rapport de couche &amp;mince :</translation>
    </message>
    <message>
        <source>A cell between two surface triangles becomes a prism or a pyramid when its height is below this ratio times its triangles&apos; size.</source>
        <translation>Une cellule entre deux triangles de surface devient un prisme ou une pyramide quand sa hauteur est inférieure à ce rapport fois la taille de ses triangles.</translation>
    </message>
    <message>
        <source>Volume CVT &amp;iterations:</source>
        <translation>&amp;Itérations du CVT volumique :</translation>
    </message>
    <message>
        <source>Lloyd iterations of the volumetric centroidal Voronoi diagram.</source>
        <translation>Itérations de Lloyd du diagramme de Voronoï centroïdal volumique.</translation>
    </message>
    <message>
        <source>Largest quad &amp;warp:</source>
        <translation>&amp;Gauchissement maximal des quadrangles :</translation>
    </message>
    <message>
        <source>Angle between the two halves of a prism&apos;s or pyramid&apos;s quad face above which the cell is left to the tets.</source>
        <translation>Angle entre les deux moitiés d&apos;une face quadrangulaire de prisme ou de pyramide au-delà duquel la cellule est laissée aux tétraèdres.</translation>
    </message>
    <message>
        <source>Sur&amp;face site iterations:</source>
        <translation>Itérations des sites de sur&amp;face :</translation>
    </message>
    <message>
        <source>Lloyd steps moving the sites whose cell meets a surface to the centroid of their restricted cell; 0 turns them off.</source>
        <translation>Pas de Lloyd qui déplacent les sites dont la cellule touche une surface vers le centroïde de leur cellule restreinte ; 0 les désactive.</translation>
    </message>
    <message>
        <source>Transition &amp;pyramid height:</source>
        <translation>Hauteur des &amp;pyramides de transition :</translation>
    </message>
    <message>
        <source>Apex height of a pyramid on a quad face that meets the tets, over the square root of the quad&apos;s area.</source>
        <translation>Hauteur du sommet d&apos;une pyramide posée sur une face quadrangulaire qui touche les tétraèdres, rapportée à la racine carrée de l&apos;aire du quadrangle.</translation>
    </message>
    <message>
        <source>× feature distance</source>
        <translation>× distance des objets</translation>
    </message>
    <message>
        <source>Cells near c&amp;lose features:</source>
        <translation>Cellules près d&apos;objets pr&amp;oches :</translation>
    </message>
    <message>
        <source>Near two features that do not meet (the two lines of a small fault throw, close corners), cells are at most this times their distance, so that both are kept without needles; the sites grow accordingly, to at most 4 times those asked. Use it with the strip factor at 0 to keep small throws rather than remove them; 0 turns it off.</source>
        <translation>Près de deux objets qui ne se touchent pas (les deux lignes d&apos;un petit rejet de faille, des coins proches), les cellules mesurent au plus ce facteur fois leur distance, pour garder les deux sans aiguilles ; les sites augmentent d&apos;autant, jusqu&apos;à 4 fois ceux demandés. À utiliser avec le facteur de bandes à 0 pour garder les petits rejets plutôt que de les supprimer ; 0 le désactive.</translation>
    </message>
    <message>
        <source>&amp;Pin sites on close features</source>
        <translation>&amp;Fixer des sites sur les éléments proches</translation>
    </message>
    <message>
        <source>&amp;Vertex-dual tets, smallest angle:</source>
        <translation>Plus petit angle des tétraèdres duaux des sommets de &amp;Voronoï :</translation>
    </message>
    <message>
        <source>Where four Voronoi cells meet, the tet of their sites, or of their points on the surfaces when the cells are cut, is kept when it and its neighbours have no dihedral angle below this; 180 leaves the whole volume to TetGen&apos;s tets.</source>
        <translation>Là où quatre cellules de Voronoï se rencontrent, le tétraèdre de leurs sites, ou de leurs points sur les surfaces quand les cellules sont coupées, est gardé si ni lui ni ses voisins n&apos;ont d&apos;angle dièdre sous cette valeur ; 180 laisse tout le volume aux tétraèdres de TetGen.</translation>
    </message>
    <message>
        <source>Leave &amp;cut Voronoi vertices to TetGen</source>
        <translation>Laisser à TetGen les sommets de Voronoï &amp;coupés</translation>
    </message>
    <message>
        <source>Where the four Voronoi cells of a vertex meet a surface, TetGen&apos;s tets fill the place instead of the tet linking their points on the surfaces and their sites (Fig. 5.4).</source>
        <translation>Là où les quatre cellules de Voronoï d&apos;un sommet rencontrent une surface, les tétraèdres de TetGen remplissent la place au lieu du tétraèdre reliant leurs points sur les surfaces et leurs sites (Fig. 5.4).</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Features smaller than this may be simplified: parts closer than it are merged, thin strips narrower than it and the strip factor are removed; 0 simplifies nothing and pins sites on close features. -1 (Auto): nothing merged, thin strips removed by the strip factor alone. At most a tenth of the bounding-box diagonal.</source>
        <translation>Les éléments plus petits que cette valeur peuvent être simplifiés : les parties plus proches sont fusionnées, les bandes minces plus étroites qu&apos;elle et que le facteur de bande sont retirées ; 0 ne simplifie rien et fixe des sites sur les éléments proches. -1 (Auto) : rien n&apos;est fusionné, les bandes minces sont retirées selon le seul facteur de bande. Au plus un dixième de la diagonale de la boîte englobante.</translation>
    </message>
    <message>
        <source>Refinement rounds put sites on the corners and lines around each topology change, as close as the nearest other feature, and grade the surfaces around them: more features are kept, with up to 4 times the sites asked plus the sites pinned on the features (9 times in all on an 8-fault network at 1000 sites), and more triangles under 30°. Always on when d_resolution is 0.</source>
        <translation>Les passes de raffinement placent des sites sur les coins et les lignes autour de chaque changement de topologie, aussi près que l&apos;élément voisin le plus proche, et graduent les surfaces autour : plus d&apos;éléments sont gardés, avec jusqu&apos;à 4 fois les sites demandés plus les sites fixés sur les éléments (9 fois en tout sur un réseau de 8 failles à 1000 sites), et plus de triangles sous 30°. Toujours actif quand d_resolution vaut 0.</translation>
    </message>
</context>
<context>
    <name>stratamesh::ProjectWorkflow</name>
    <message>
        <source>edge %1</source>
        <translation>arête %1</translation>
    </message>
    <message>
        <source>%1 sites</source>
        <translation>%1 sites</translation>
    </message>
    <message numerus="yes">
        <source>, %n iteration(s)</source>
        <translation>
            <numerusform>, %n itération</numerusform>
            <numerusform>, %n itérations</numerusform>
        </translation>
    </message>
    <message>
        <source>, d_resolution %1</source>
        <translation>, d_resolution %1</translation>
    </message>
    <message>
        <source>, adaptive</source>
        <translation>, adaptatif</translation>
    </message>
    <message>
        <source>Locate the Input Model %1</source>
        <translation>Retrouver le modèle d&apos;entrée %1</translation>
    </message>
    <message>
        <source>Open &amp;Project…</source>
        <translation>Ouvrir un &amp;projet…</translation>
    </message>
    <message>
        <source>Open a StrataMesh project: its model, remesh runs and reviews</source>
        <translation>Ouvrir un projet StrataMesh : son modèle, ses remaillages et leurs revues</translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation>&amp;Enregistrer le projet</translation>
    </message>
    <message>
        <source>Save the remesh runs, their results and reviews as a project</source>
        <translation>Enregistrer les remaillages, leurs résultats et leurs revues dans un projet</translation>
    </message>
    <message>
        <source>Save Project As…</source>
        <translation>Enregistrer le projet sous…</translation>
    </message>
    <message>
        <source>Save the project under another name</source>
        <translation>Enregistrer le projet sous un autre nom</translation>
    </message>
    <message>
        <source>Runs</source>
        <translation>Remaillages</translation>
    </message>
    <message>
        <source>R&amp;uns</source>
        <translation>Rema&amp;illages</translation>
    </message>
    <message>
        <source>The project&apos;s runs and reviews have not been saved.</source>
        <translation>Les remaillages du projet et leurs revues n&apos;ont pas été enregistrés.</translation>
    </message>
    <message>
        <source>Show Run %1</source>
        <translation>Afficher le remaillage %1</translation>
    </message>
    <message>
        <source>Showing run %1</source>
        <translation>Remaillage %1 affiché</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Ouvrir un projet</translation>
    </message>
    <message>
        <source>StrataMesh projects (*.smproj)</source>
        <translation>Projets StrataMesh (*.smproj)</translation>
    </message>
    <message>
        <source>Could not open the project %1</source>
        <translation>Impossible d&apos;ouvrir le projet %1</translation>
    </message>
    <message>
        <source>The project&apos;s input model is not where the project says: %1</source>
        <translation>Le modèle d&apos;entrée du projet n&apos;est pas à l&apos;endroit indiqué : %1</translation>
    </message>
    <message>
        <source>Project not opened: its input model %1 is missing</source>
        <translation>Projet non ouvert : son modèle d&apos;entrée %1 est introuvable</translation>
    </message>
    <message>
        <source>Could not open the project&apos;s input model — see Messages</source>
        <translation>Impossible d&apos;ouvrir le modèle d&apos;entrée du projet — voir Messages</translation>
    </message>
    <message>
        <source>Run %1: its review was not read (%2)</source>
        <translation>Remaillage %1 : sa revue n&apos;a pas été lue (%2)</translation>
    </message>
    <message numerus="yes">
        <source>Project %1 opened: %n run(s), read from its folder without remeshing</source>
        <translation>
            <numerusform>Projet %1 ouvert : %n remaillage, relu depuis son dossier sans remailler</numerusform>
            <numerusform>Projet %1 ouvert : %n remaillages, relus depuis son dossier sans remailler</numerusform>
        </translation>
    </message>
    <message>
        <source>The input model was found at %1: save the project to keep it</source>
        <translation>Le modèle d&apos;entrée a été trouvé à %1 : enregistrez le projet pour le garder</translation>
    </message>
    <message>
        <source>Opened project %1</source>
        <translation>Projet %1 ouvert</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Enregistrer le projet</translation>
    </message>
    <message>
        <source>Could not save the project</source>
        <translation>Impossible d&apos;enregistrer le projet</translation>
    </message>
    <message numerus="yes">
        <source>Project saved with %n run(s)</source>
        <translation>
            <numerusform>Projet enregistré avec %n remaillage</numerusform>
            <numerusform>Projet enregistré avec %n remaillages</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Compare Runs %1 and %2</source>
        <translation>Comparer les remaillages %1 et %2</translation>
    </message>
    <message>
        <source>Show Input vs Output</source>
        <translation>Afficher l&apos;entrée et la sortie</translation>
    </message>
    <message>
        <source>Comparing run %1 with run %2</source>
        <translation>Comparaison du remaillage %1 avec le remaillage %2</translation>
    </message>
    <message>
        <source>Run %1: %2 sites, %3 triangles</source>
        <translation>Remaillage %1 : %2 sites, %3 triangles</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
    </message>
    <message>
        <source>Run %1</source>
        <translation>Remaillage %1</translation>
    </message>
</context>
<context>
    <name>stratamesh::RecentFiles</name>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>File not found: %1</source>
        <translation>Fichier introuvable : %1</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Effacer le menu</translation>
    </message>
    <message>
        <source>Forget the files opened before</source>
        <translation>Oublier les fichiers ouverts auparavant</translation>
    </message>
    <message>
        <source>no file opened yet</source>
        <translation>aucun fichier ouvert auparavant</translation>
    </message>
</context>
<context>
    <name>stratamesh::RemeshController</name>
    <message>
        <source>Remeshing</source>
        <translation>Remaillage</translation>
    </message>
    <message>
        <source>Remeshing stopped without a result</source>
        <translation>Le remaillage s&apos;est arrêté sans résultat</translation>
    </message>
</context>
<context>
    <name>stratamesh::RemeshDialog</name>
    <message>
        <source>Remesh Model</source>
        <translation>Remailler le modèle</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>Résolution</translation>
    </message>
    <message>
        <source>&amp;Remesh</source>
        <translation>&amp;Remailler</translation>
    </message>
</context>
<context>
    <name>stratamesh::RemeshWorkflow</name>
    <message>
        <source>&amp;Remesh…</source>
        <translation>&amp;Remailler…</translation>
    </message>
    <message>
        <source>Remesh all the surfaces at a chosen resolution, keeping the model conformal</source>
        <translation>Remailler toutes les surfaces à la résolution choisie en gardant le modèle conforme</translation>
    </message>
    <message>
        <source>&amp;Cancel Remeshing</source>
        <translation>&amp;Annuler le remaillage</translation>
    </message>
    <message>
        <source>Stop the remeshing; the input model is left as it is</source>
        <translation>Arrêter le remaillage ; le modèle d&apos;entrée reste tel quel</translation>
    </message>
    <message>
        <source>Save Remeshed Model &amp;As…</source>
        <translation>Enregistrer le modèle remaillé &amp;sous…</translation>
    </message>
    <message>
        <source>Write the remeshed model as a Gocad, RINGMesh, Gmsh or VTK file</source>
        <translation>Écrire le modèle remaillé dans un fichier Gocad, RINGMesh, Gmsh ou VTK</translation>
    </message>
    <message>
        <source>Remeshing %1…</source>
        <translation>Remaillage de %1…</translation>
    </message>
    <message numerus="yes">
        <source>Remeshed with %1 sites in %2 s: %3 triangles, %n simplification(s) recorded</source>
        <translation>
            <numerusform>Remaillé avec %1 sites en %2 s : %3 triangles, %n simplification enregistrée</numerusform>
            <numerusform>Remaillé avec %1 sites en %2 s : %3 triangles, %n simplifications enregistrées</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The remeshed model is NOT valid: %n problem(s) left after local refinement; saving it is at your own risk</source>
        <translation>
            <numerusform>Le modèle remaillé n’est PAS valide : %n problème après le raffinement local ; l’enregistrer est à vos risques</numerusform>
            <numerusform>Le modèle remaillé n’est PAS valide : %n problèmes après le raffinement local ; l’enregistrer est à vos risques</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remeshed, NOT valid: %n problem(s) — see Messages</source>
        <translation>
            <numerusform>Remaillé, NON valide : %n problème — voir Messages</numerusform>
            <numerusform>Remaillé, NON valide : %n problèmes — voir Messages</numerusform>
        </translation>
    </message>
    <message>
        <source>Remeshing failed: %1</source>
        <translation>Échec du remaillage : %1</translation>
    </message>
    <message>
        <source>Remeshing failed — see Messages</source>
        <translation>Échec du remaillage — voir Messages</translation>
    </message>
    <message>
        <source>Remeshing cancelled</source>
        <translation>Remaillage annulé</translation>
    </message>
    <message>
        <source>Input: %1</source>
        <translation>Entrée : %1</translation>
    </message>
    <message>
        <source>Output: %1 sites, %2 triangles</source>
        <translation>Sortie : %1 sites, %2 triangles</translation>
    </message>
    <message>
        <source>Save Remeshed Model</source>
        <translation>Enregistrer le modèle remaillé</translation>
    </message>
    <message>
        <source>Remeshed model saved</source>
        <translation>Modèle remaillé enregistré</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Could not save the remeshed model</source>
        <translation>Impossible d&apos;enregistrer le modèle remaillé</translation>
    </message>
    <message>
        <source>Remeshing cancelled: the previous result, if any, is kept</source>
        <translation>Remaillage annulé : le résultat précédent, s&apos;il existe, est conservé</translation>
    </message>
    <message>
        <source>The remeshed model has not been saved.</source>
        <translation>Le modèle remaillé n&apos;a pas été enregistré.</translation>
    </message>
    <message>
        <source>Export Re&amp;view as CSV…</source>
        <translation>Exporter le &amp;contrôle en CSV…</translation>
    </message>
    <message>
        <source>Export Review as CSV: every record with its decision and note</source>
        <translation>Exporter le contrôle en CSV : chaque enregistrement avec sa décision et sa note</translation>
    </message>
    <message>
        <source>Write every simplification with its decision and note as a CSV table</source>
        <translation>Écrire chaque simplification avec sa décision et sa note dans un tableau CSV</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>Contrôle</translation>
    </message>
    <message>
        <source>&amp;Review</source>
        <translation>&amp;Contrôle</translation>
    </message>
    <message numerus="yes">
        <source>Remeshed: %n simplification(s) — see Review</source>
        <translation>
            <numerusform>Remaillé : %n simplification — voir Contrôle</numerusform>
            <numerusform>Remaillé : %n simplifications — voir Contrôle</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Review</source>
        <translation>Exporter le contrôle</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>Tableau CSV (*.csv)</translation>
    </message>
    <message>
        <source>Review exported: %1 of %2 records reviewed</source>
        <translation>Contrôle exporté : %1 enregistrements sur %2 examinés</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exporté</translation>
    </message>
    <message>
        <source>Could not export the review</source>
        <translation>Impossible d’exporter le contrôle</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
    </message>
    <message>
        <source>no remeshed model yet</source>
        <translation>pas encore de modèle remaillé</translation>
    </message>
    <message>
        <source>no remesh is running</source>
        <translation>aucun remaillage n&apos;est en cours</translation>
    </message>
    <message numerus="yes">
        <source>… (%n in all)</source>
        <translation>
            <numerusform>… (%n en tout)</numerusform>
            <numerusform>… (%n en tout)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n topology change(s) left where refinement stopped (%1 of %2 rounds, %3 sites), involving %4 — see Review</source>
        <translation>
            <numerusform>%n changement de topologie restant là où le raffinement s&apos;est arrêté (%1 passes sur %2, %3 sites), concernant %4 — voir Contrôle</numerusform>
            <numerusform>%n changements de topologie restants là où le raffinement s&apos;est arrêté (%1 passes sur %2, %3 sites), concernant %4 — voir Contrôle</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n topology change(s), involving %1 — see Review</source>
        <translation>
            <numerusform>%n changement de topologie, concernant %1 — voir Contrôle</numerusform>
            <numerusform>%n changements de topologie, concernant %1 — voir Contrôle</numerusform>
        </translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>Qualité</translation>
    </message>
    <message>
        <source>&amp;Quality</source>
        <translation>&amp;Qualité</translation>
    </message>
</context>
<context>
    <name>stratamesh::ReviewPanel</name>
    <message>
        <source>&amp;Accept</source>
        <translation>&amp;Accepter</translation>
    </message>
    <message>
        <source>Accept the selected simplification (A; again to reopen it)</source>
        <translation>Accepter la simplification sélectionnée (A ; une seconde fois pour la rouvrir)</translation>
    </message>
    <message>
        <source>&amp;Flag</source>
        <translation>&amp;Signaler</translation>
    </message>
    <message>
        <source>Flag the selected simplification for a closer look (F; again to reopen it)</source>
        <translation>Signaler la simplification sélectionnée pour un examen plus attentif (F ; une seconde fois pour la rouvrir)</translation>
    </message>
    <message>
        <source>&amp;Note</source>
        <translation>&amp;Note</translation>
    </message>
    <message>
        <source>Write a note on the selected simplification (N; Enter keeps it)</source>
        <translation>Écrire une note sur la simplification sélectionnée (N ; Entrée la garde)</translation>
    </message>
    <message>
        <source>&amp;Previous</source>
        <translation>&amp;Précédent</translation>
    </message>
    <message>
        <source>Go to the previous record and show it in both views (K or Up)</source>
        <translation>Aller à l’enregistrement précédent et le montrer dans les deux vues (K ou Haut)</translation>
    </message>
    <message>
        <source>Ne&amp;xt</source>
        <translation>Sui&amp;vant</translation>
    </message>
    <message>
        <source>Go to the next record and show it in both views (J or Down)</source>
        <translation>Aller à l’enregistrement suivant et le montrer dans les deux vues (J ou Bas)</translation>
    </message>
    <message>
        <source>%1 of %2 reviewed</source>
        <translation>%1 sur %2 examinés</translation>
    </message>
</context>
<context>
    <name>stratamesh::ReviewTableModel</name>
    <message>
        <source>Accepted</source>
        <translation>Acceptée</translation>
    </message>
    <message>
        <source>Flagged</source>
        <translation>Signalée</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>À examiner</translation>
    </message>
    <message>
        <source>Decision</source>
        <translation>Décision</translation>
    </message>
    <message>
        <source>Review note</source>
        <translation>Note de contrôle</translation>
    </message>
    <message>
        <source>#</source>
        <translation>n°</translation>
    </message>
</context>
<context>
    <name>stratamesh::RunsPanel</name>
    <message>
        <source>Run</source>
        <translation>Remaillage</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Paramètres</translation>
    </message>
    <message>
        <source>Sites</source>
        <translation>Sites</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>Valid</source>
        <translation>Valide</translation>
    </message>
    <message>
        <source>Hausdorff (% diag.)</source>
        <translation>Hausdorff (% diag.)</translation>
    </message>
    <message>
        <source>Mean Q</source>
        <translation>Q moyen</translation>
    </message>
    <message>
        <source>Reviewed</source>
        <translation>Revus</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>oui</translation>
    </message>
    <message>
        <source>NO</source>
        <translation>NON</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message>
        <source>Compare…</source>
        <translation>Comparer…</translation>
    </message>
    <message>
        <source>Show one run in the input view and another in the output view</source>
        <translation>Afficher un remaillage dans la vue d&apos;entrée et un autre dans la vue de sortie</translation>
    </message>
    <message>
        <source>Input vs Output</source>
        <translation>Entrée et sortie</translation>
    </message>
    <message>
        <source>Show the input model again beside the run shown</source>
        <translation>Afficher de nouveau le modèle d&apos;entrée à côté du remaillage affiché</translation>
    </message>
    <message>
        <source>Compare Runs</source>
        <translation>Comparer des remaillages</translation>
    </message>
    <message>
        <source>Input view:</source>
        <translation>Vue d&apos;entrée :</translation>
    </message>
    <message>
        <source>Output view:</source>
        <translation>Vue de sortie :</translation>
    </message>
    <message>
        <source>Run %1: %2</source>
        <translation>Remaillage %1 : %2</translation>
    </message>
</context>
<context>
    <name>stratamesh::ScriptRunner</name>
    <message>
        <source>it could not start (no model shown, or another run is going on)</source>
        <translation>elle n’a pas pu démarrer (aucun modèle affiché, ou un autre calcul est en cours)</translation>
    </message>
    <message>
        <source>this colouring is not available now (the distance needs a remesh before)</source>
        <translation>cette coloration n’est pas disponible pour l’instant (la distance demande un remaillage avant)</translation>
    </message>
    <message>
        <source>it was cancelled or failed</source>
        <translation>elle a été annulée ou a échoué</translation>
    </message>
    <message>
        <source>step %1 (%2) failed: %3</source>
        <translation>l’étape %1 (%2) a échoué : %3</translation>
    </message>
</context>
<context>
    <name>stratamesh::StepsWorkflow</name>
    <message>
        <source>Steps</source>
        <translation>Étapes</translation>
    </message>
    <message>
        <source>S&amp;teps</source>
        <translation>É&amp;tapes</translation>
    </message>
    <message>
        <source>Show Problems</source>
        <translation>Voir les problèmes</translation>
    </message>
    <message>
        <source>Show the Messages, where each validity problem of the model is listed; a click on one flies the views to it</source>
        <translation>Afficher les messages, où chaque problème de validité du modèle est listé ; un clic sur l&apos;un d&apos;eux y amène les vues</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Vérification</translation>
    </message>
    <message>
        <source>Complexity</source>
        <translation>Complexité</translation>
    </message>
    <message>
        <source>Remesh</source>
        <translation>Remaillage</translation>
    </message>
    <message>
        <source>Volume</source>
        <translation>Volume</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Open a model (File &gt; Open Model…).</source>
        <translation>Ouvrir un modèle (Fichier &gt; Ouvrir un modèle…).</translation>
    </message>
    <message>
        <source>%1: no validity problem found.</source>
        <translation>%1 : aucun problème de validité.</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n validity problem(s) — see Messages.</source>
        <translation>
            <numerusform>%1 : %n problème de validité — voir Messages.</numerusform>
            <numerusform>%1 : %n problèmes de validité — voir Messages.</numerusform>
        </translation>
    </message>
    <message>
        <source>Measured with %1 Voronoi cells.</source>
        <translation>Mesurée avec %1 cellules de Voronoï.</translation>
    </message>
    <message>
        <source>Elements per Voronoi cell as a heat map (ch. 3).</source>
        <translation>Éléments par cellule de Voronoï en carte de chaleur (chap. 3).</translation>
    </message>
    <message>
        <source>%1 sites: %2 vertices, %3 triangles, %4.</source>
        <translation>%1 sites : %2 sommets, %3 triangles, %4.</translation>
    </message>
    <message>
        <source>valid</source>
        <translation>valide</translation>
    </message>
    <message>
        <source>not valid</source>
        <translation>non valide</translation>
    </message>
    <message>
        <source>All surfaces at once at a chosen resolution (ch. 4).</source>
        <translation>Toutes les surfaces à la fois, à la résolution choisie (chap. 4).</translation>
    </message>
    <message>
        <source>TetGen meshes made.</source>
        <translation>Maillages TetGen faits.</translation>
    </message>
    <message>
        <source>Hybrid mesh of %1 cells.</source>
        <translation>Maillage hybride de %1 cellules.</translation>
    </message>
    <message>
        <source>TetGen meshes of input and remesh, or a hybrid mesh (ch. 5).</source>
        <translation>Maillages TetGen de l&apos;entrée et du remaillage, ou un maillage hybride (chap. 5).</translation>
    </message>
    <message>
        <source>The input, the remesh or a volume mesh in another format.</source>
        <translation>L&apos;entrée, le remaillage ou un maillage volumique dans un autre format.</translation>
    </message>
</context>
<context>
    <name>stratamesh::StudyWindow</name>
    <message>
        <source>Task</source>
        <translation>Tâche</translation>
    </message>
    <message>
        <source>Sites asked</source>
        <translation>Sites demandés</translation>
    </message>
    <message>
        <source>Mean triangle quality Q against the resolution</source>
        <translation>Qualité moyenne Q des triangles selon la résolution</translation>
    </message>
    <message>
        <source>Mean Q</source>
        <translation>Q moyen</translation>
    </message>
    <message>
        <source>Output triangles against the resolution</source>
        <translation>Triangles produits selon la résolution</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>Task %1 — %2: input (left), remesh (right)</source>
        <translation>Tâche %1 — %2 : entrée (à gauche), remaillage (à droite)</translation>
    </message>
    <message>
        <source>Cannot open the task</source>
        <translation>Impossible d’ouvrir la tâche</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>Étude</translation>
    </message>
    <message>
        <source>Study %1</source>
        <translation>Étude %1</translation>
    </message>
    <message>
        <source>Filter the rows (model, status, error…)</source>
        <translation>Filtrer les lignes (modèle, état, erreur…)</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>Qualité</translation>
    </message>
    <message>
        <source>Element counts</source>
        <translation>Nombres d’éléments</translation>
    </message>
    <message numerus="yes">
        <source>%n task(s), %1 ok; double-click a row to see its input and output</source>
        <translation>
            <numerusform>%n tâche, %1 réussie ; double-cliquer sur une ligne pour voir son entrée et sa sortie</numerusform>
            <numerusform>%n tâches, %1 réussies ; double-cliquer sur une ligne pour voir son entrée et sa sortie</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stratamesh::StudyWorkflow</name>
    <message>
        <source>Open S&amp;tudy…</source>
        <translation>Ouvrir une é&amp;tude…</translation>
    </message>
    <message>
        <source>Show the table of a study run by stratamesh-cli study (.smstudy or study.json)</source>
        <translation>Afficher le tableau d’une étude lancée par stratamesh-cli study (.smstudy ou study.json)</translation>
    </message>
    <message>
        <source>Open Study</source>
        <translation>Ouvrir une étude</translation>
    </message>
    <message>
        <source>StrataMesh studies (*.smstudy);;Gathered study tables (study.json)</source>
        <translation>Études StrataMesh (*.smstudy);;Tableaux d’études rassemblés (study.json)</translation>
    </message>
    <message>
        <source>Cannot open the study</source>
        <translation>Impossible d’ouvrir l’étude</translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshController</name>
    <message>
        <source>Tetrahedralising the input</source>
        <translation>Tétraédrisation du modèle d&apos;entrée</translation>
    </message>
    <message>
        <source>Tetrahedralisation stopped without a result</source>
        <translation>La tétraédrisation s&apos;est arrêtée sans résultat</translation>
    </message>
    <message>
        <source>Tetrahedralising the input and the remesh</source>
        <translation>Tétraédrisation du modèle d&apos;entrée et du remaillage</translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshDialog</name>
    <message>
        <source>Input and &amp;remesh</source>
        <translation>Entrée et &amp;remaillage</translation>
    </message>
    <message>
        <source>&amp;Input only</source>
        <translation>&amp;Entrée seule</translation>
    </message>
    <message>
        <source>Tetrahedralise</source>
        <translation>Tétraédriser</translation>
    </message>
    <message>
        <source>Models</source>
        <translation>Modèles</translation>
    </message>
    <message>
        <source>Remesh the model first</source>
        <translation>Remailler d&apos;abord le modèle</translation>
    </message>
    <message>
        <source>&amp;Tetrahedralise</source>
        <translation>&amp;Tétraédriser</translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshPanel</name>
    <message>
        <source>ok</source>
        <translation>réussi</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>interrompu</translation>
    </message>
    <message>
        <source>timed out</source>
        <translation>temps dépassé</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>mémoire épuisée</translation>
    </message>
    <message>
        <source>killed</source>
        <translation>tué</translation>
    </message>
    <message>
        <source>invalid input</source>
        <translation>entrée invalide</translation>
    </message>
    <message>
        <source>TetGen was not run on the input: %1</source>
        <translation>TetGen n&apos;a pas été lancé sur le modèle d&apos;entrée : %1</translation>
    </message>
    <message>
        <source>TetGen was not run on the remesh: %1</source>
        <translation>TetGen n&apos;a pas été lancé sur le remaillage : %1</translation>
    </message>
    <message>
        <source>TetGen failed on the input after %1 s: %2</source>
        <translation>Échec de TetGen sur le modèle d&apos;entrée après %1 s : %2</translation>
    </message>
    <message>
        <source>TetGen failed on the remesh after %1 s: %2</source>
        <translation>Échec de TetGen sur le remaillage après %1 s : %2</translation>
    </message>
    <message>
        <source>C&amp;olour tets by:</source>
        <translation>C&amp;olorer les tétraèdres par :</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Région</translation>
    </message>
    <message>
        <source>Min dihedral angle</source>
        <translation>Angle dièdre minimal</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Entrée</translation>
    </message>
    <message>
        <source>Remesh</source>
        <translation>Remaillage</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Issue</translation>
    </message>
    <message>
        <source>Tetrahedra</source>
        <translation>Tétraèdres</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>Slivers (min dihedral &lt; 5°)</source>
        <translation>Tétraèdres plats (dièdre min. &lt; 5°)</translation>
    </message>
    <message>
        <source>Min dihedral (°)</source>
        <translation>Dièdre min. (°)</translation>
    </message>
    <message>
        <source>TetGen time (s)</source>
        <translation>Temps TetGen (s)</translation>
    </message>
</context>
<context>
    <name>stratamesh::TetmeshWorkflow</name>
    <message>
        <source>&amp;Tetrahedralise…</source>
        <translation>&amp;Tétraédriser…</translation>
    </message>
    <message>
        <source>Mesh the regions of the input and of the remesh with TetGen and compare the tetrahedra</source>
        <translation>Mailler les régions du modèle d&apos;entrée et du remaillage avec TetGen et comparer les tétraèdres</translation>
    </message>
    <message>
        <source>Cancel &amp;Tetrahedralisation</source>
        <translation>Annuler la &amp;tétraédrisation</translation>
    </message>
    <message>
        <source>Stop TetGen; nothing is kept of this run</source>
        <translation>Arrêter TetGen ; rien n&apos;est gardé de cette exécution</translation>
    </message>
    <message>
        <source>Tetrahedra</source>
        <translation>Tétraèdres</translation>
    </message>
    <message>
        <source>&amp;Tetrahedra</source>
        <translation>&amp;Tétraèdres</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Région</translation>
    </message>
    <message>
        <source>Min dihedral
angle (°)</source>
        <translation>Angle dièdre
min. (°)</translation>
    </message>
    <message>
        <source>Tetrahedralising %1…</source>
        <translation>Tétraédrisation de %1…</translation>
    </message>
    <message>
        <source>Input: %1 tets, %2 slivers, min dihedral %3° in %4 s</source>
        <translation>Entrée : %1 tétraèdres, %2 tétraèdres plats, angle dièdre min. %3° en %4 s</translation>
    </message>
    <message>
        <source>Remesh: %1 tets, %2 slivers, min dihedral %3° in %4 s</source>
        <translation>Remaillage : %1 tétraèdres, %2 tétraèdres plats, angle dièdre min. %3° en %4 s</translation>
    </message>
    <message>
        <source>TetGen failed on a model — see Tetrahedra</source>
        <translation>Échec de TetGen sur un modèle — voir Tétraèdres</translation>
    </message>
    <message>
        <source>Tetrahedralisation failed: %1</source>
        <translation>Échec de la tétraédrisation : %1</translation>
    </message>
    <message>
        <source>Tetrahedralisation failed — see Messages</source>
        <translation>Échec de la tétraédrisation — voir Messages</translation>
    </message>
    <message>
        <source>Tetrahedralisation cancelled</source>
        <translation>Tétraédrisation annulée</translation>
    </message>
    <message>
        <source>Tetrahedralisation cancelled: the previous meshes, if any, are kept</source>
        <translation>Tétraédrisation annulée : les maillages précédents, s&apos;il y en a, sont conservés</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
    </message>
    <message>
        <source>TetGen is not running</source>
        <translation>TetGen n&apos;est pas en cours</translation>
    </message>
    <message>
        <source>Tetrahedralised — see Tetrahedra and Quality</source>
        <translation>Tétraédrisé — voir Tétraèdres et Qualité</translation>
    </message>
</context>
<context>
    <name>stratamesh::ViewWorkflow</name>
    <message>
        <source>&amp;Colour By</source>
        <translation>&amp;Colorer selon</translation>
    </message>
    <message>
        <source>&amp;Entity</source>
        <translation>&amp;Entité</translation>
    </message>
    <message>
        <source>Triangle &amp;Min Angle</source>
        <translation>Angle &amp;minimal des triangles</translation>
    </message>
    <message>
        <source>Triangle &amp;Quality Q</source>
        <translation>&amp;Qualité Q des triangles</translation>
    </message>
    <message>
        <source>&amp;Distance to the Other Model</source>
        <translation>&amp;Distance à l’autre modèle</translation>
    </message>
    <message>
        <source>Colour each vertex by its distance to the other model (needs a remesh)</source>
        <translation>Colorer chaque sommet selon sa distance à l’autre modèle (après un remaillage)</translation>
    </message>
    <message>
        <source>&amp;Reverse Colours</source>
        <translation>&amp;Inverser les couleurs</translation>
    </message>
    <message>
        <source>Swap the ends of the colour map (bad is yellow by default)</source>
        <translation>Échanger les extrémités de l’échelle de couleurs (le mauvais est jaune par défaut)</translation>
    </message>
    <message>
        <source>C&amp;lip Plane</source>
        <translation>P&amp;lan de coupe</translation>
    </message>
    <message>
        <source>&amp;Clip Both Views</source>
        <translation>&amp;Couper les deux vues</translation>
    </message>
    <message>
        <source>Cut the surfaces and the tet meshes of both views with one plane</source>
        <translation>Couper les surfaces et les maillages tétraédriques des deux vues par un même plan</translation>
    </message>
    <message>
        <source>Across &amp;X (east)</source>
        <translation>Selon &amp;X (est)</translation>
    </message>
    <message>
        <source>Across &amp;Y (north)</source>
        <translation>Selon &amp;Y (nord)</translation>
    </message>
    <message>
        <source>Across &amp;Z (up)</source>
        <translation>Selon &amp;Z (haut)</translation>
    </message>
    <message>
        <source>Position of the clip plane across the models</source>
        <translation>Position du plan de coupe à travers les modèles</translation>
    </message>
    <message>
        <source>Next &amp;Worst Triangle</source>
        <translation>&amp;Pire triangle suivant</translation>
    </message>
    <message>
        <source>Fly to the triangles of the output (or the input) by increasing quality Q</source>
        <translation>Aller aux triangles de la sortie (ou de l’entrée) par qualité Q croissante</translation>
    </message>
    <message>
        <source>Colour by %1</source>
        <translation>Colorer selon %1</translation>
    </message>
    <message>
        <source>Reverse Colours</source>
        <translation>Inverser les couleurs</translation>
    </message>
    <message>
        <source>Unreverse Colours</source>
        <translation>Rétablir le sens des couleurs</translation>
    </message>
    <message>
        <source>Min angle (°)</source>
        <translation>Angle min. (°)</translation>
    </message>
    <message>
        <source>Q</source>
        <translation>Q</translation>
    </message>
    <message>
        <source>Distance
(model units)</source>
        <translation>Distance
(unités du modèle)</translation>
    </message>
    <message>
        <source>%1 triangles highlighted for a bar of %2</source>
        <translation>%1 triangles mis en évidence pour une barre de %2</translation>
    </message>
    <message>
        <source>min angle</source>
        <translation>angle min.</translation>
    </message>
    <message numerus="yes">
        <source>%n triangle(s) of the output highlighted: %1 in [%2, %3]</source>
        <translation>
            <numerusform>%n triangle de la sortie mis en évidence : %1 dans [%2, %3]</numerusform>
            <numerusform>%n triangles de la sortie mis en évidence : %1 dans [%2, %3]</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n triangle(s) of the input highlighted: %1 in [%2, %3]</source>
        <translation>
            <numerusform>%n triangle de l’entrée mis en évidence : %1 dans [%2, %3]</numerusform>
            <numerusform>%n triangles de l’entrée mis en évidence : %1 dans [%2, %3]</numerusform>
        </translation>
    </message>
    <message>
        <source>Worst triangle %1 of the output: surface %2, triangle %3, Q = %4</source>
        <translation>Pire triangle n° %1 de la sortie : surface %2, triangle %3, Q = %4</translation>
    </message>
    <message>
        <source>Worst triangle %1 of the input: surface %2, triangle %3, Q = %4</source>
        <translation>Pire triangle n° %1 de l’entrée : surface %2, triangle %3, Q = %4</translation>
    </message>
    <message>
        <source>Clip Both Views</source>
        <translation>Couper les deux vues</translation>
    </message>
    <message>
        <source>Remove the Clip Plane</source>
        <translation>Retirer le plan de coupe</translation>
    </message>
    <message>
        <source>Move the Clip Plane</source>
        <translation>Déplacer le plan de coupe</translation>
    </message>
    <message>
        <source>Clear &amp;Highlight</source>
        <translation>Effacer la &amp;mise en évidence</translation>
    </message>
    <message>
        <source>Remove the highlight of a histogram bar&apos;s triangles or of the worst triangle</source>
        <translation>Retirer la mise en évidence des triangles d’une barre d’histogramme ou du pire triangle</translation>
    </message>
    <message>
        <source>no model open</source>
        <translation>aucun modèle ouvert</translation>
    </message>
    <message>
        <source>another step is running</source>
        <translation>une autre étape est en cours</translation>
    </message>
    <message>
        <source>no remeshed model yet</source>
        <translation>pas encore de modèle remaillé</translation>
    </message>
</context>
<context>
    <name>stratamesh::Workbench</name>
    <message>
        <source>Unsaved Result</source>
        <translation>Résultat non enregistré</translation>
    </message>
    <message>
        <source>%1 Save it before it is replaced?</source>
        <translation>%1 L&apos;enregistrer avant qu&apos;il ne soit remplacé ?</translation>
    </message>
    <message>
        <source>%1 Save them before they are replaced?</source>
        <translation>%1 Les enregistrer avant qu&apos;ils ne soient remplacés ?</translation>
    </message>
</context>
<context>
    <name>stratamesh::Workflow</name>
    <message>
        <source>Cancelling…</source>
        <translation>Annulation…</translation>
    </message>
</context>
</TS>
