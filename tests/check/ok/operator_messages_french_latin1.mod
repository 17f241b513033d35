MODULE operator_messages_french_latin1
    ! Messages opérateur de la cellule de soudage (usine de Besançon).
    ! Fichier enregistré en ISO-8859-1 : é è ê à ç ô û ë ï « »
    ! Révision : ajout des messages pour l'étape de contrôle.

    CONST string MSG_START:="Démarrage du cycle - vérifier la présence pièce";
    CONST string MSG_GAS:="Pression de gaz trop faible, cycle arrêté";
    CONST string MSG_CHECK:="Contrôle visuel : cordon conforme ? «Oui» / «Non»";
    CONST string MSG_END:="Cycle terminé. Pièces soudées : ";
    CONST string MSG_ARRET:="Arrêt demandé par l'opérateur";

    VAR num nAnswer:=0;
    VAR num nWelded:=0;
    VAR num nRejected:=0;
    VAR bool bStopRequested:=FALSE;
    VAR signaldi di_gas_ok;
    VAR signaldi di_piece_presente;

    PERS tooldata tTorche:=[TRUE,[[120,0,380],[0.92388,0,0.382683,0]],[3,[0,0,150],[1,0,0,0],0,0,0]];
    CONST robtarget pDebut:=[[900,-150,450],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pFin:=[[900,150,450],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        AliasIO "DI_GazOk",di_gas_ok;
        AliasIO "DI_PiecePresente",di_piece_presente;
        TPWrite MSG_START;
        WaitDI di_piece_presente,1;
        WHILE NOT bStopRequested DO
            IF di_gas_ok=0 THEN
                TPWrite MSG_GAS;
                Stop;
            ENDIF
            souder_cordon;
            controle_visuel;
        ENDWHILE
        TPWrite MSG_END\Num:=nWelded;
    ENDPROC

    ! Soudure du cordon principal (trajectoire linéaire)
    PROC souder_cordon()
        MoveJ Offs(pDebut,0,0,80),v1000,z20,tTorche;
        MoveL pDebut,v200,fine,tTorche;
        MoveL pFin,v10,fine,tTorche;
        MoveL Offs(pFin,0,0,80),v500,z20,tTorche;
        nWelded:=nWelded+1;
    ENDPROC

    ! Contrôle par l'opérateur sur le FlexPendant
    PROC controle_visuel()
        TPReadFK nAnswer,MSG_CHECK,"Oui","Non",stEmpty,stEmpty,"Arrêt";
        TEST nAnswer
        CASE 1:
            TPWrite "Cordon accepté";
        CASE 2:
            nRejected:=nRejected+1;
            TPWrite "Pièce rejetée, total : "\Num:=nRejected;
        CASE 5:
            TPWrite MSG_ARRET;
            bStopRequested:=TRUE;
        ENDTEST
    ENDPROC

ENDMODULE
