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
        <source>Parts of features closer than this distance are merged; 0 keeps them apart. At most a tenth of the bounding-box diagonal.</source>
        <translation>Les parties d&apos;éléments plus proches que cette distance sont fusionnées ; 0 les garde séparées. Au plus un dixième de la diagonale de la boîte englobante.</translation>
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
        <source>Refinement rounds put sites on the corners and lines around each topology change, as close as the nearest other feature, and grade the surfaces around them: more features are kept, with up to 4 times the sites asked and more triangles under 30°.</source>
        <translation>Les passes de raffinement placent des sites sur les coins et les lignes autour de chaque changement de topologie, aussi près que l&apos;élément voisin le plus proche, et graduent les surfaces autour : plus d&apos;éléments sont gardés, avec jusqu&apos;à 4 fois les sites demandés et plus de triangles sous 30°.</translation>
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
