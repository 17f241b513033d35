MODULE error_handlers_retry_trynext
    ! Error recovery examples from the measuring station:
    !  - a FUNC whose handler RETURNs a substitute value
    !  - RETRY with a retry budget (RemainingRetries / ResetRetryCount)
    !  - TRYNEXT to skip one bad sample
    !  - an error handler restricted to a list of error numbers
    !  - propagation with RAISE to the caller's handler

    VAR num nSamples{8}:=[10.2,10.4,0,10.1,9.9,10.3,10.0,10.2];
    VAR num nWeights{8}:=[1,1,1,2,2,1,1,0];
    VAR num nDivisor:=0;
    VAR num nSkipped:=0;
    VAR num nIndex:=0;

    PROC main()
        VAR num nMean;
        VAR num nRatio;
        nMean:=weighted_mean(nSamples,nWeights);
        TPWrite "Weighted mean: "\Num:=nMean;
        nRatio:=safe_ratio(12,0);
        TPWrite "Ratio with zero divisor: "\Num:=nRatio;
        normalise_samples;
        read_sample_out_of_range;
        retry_with_budget;
    ENDPROC

    ! Division by zero returns a safe value from the error handler
    FUNC num safe_ratio(num a,num b)
        RETURN a/b;
    ERROR
        IF ERRNO=ERR_DIVZERO THEN
            RETURN 0;
        ENDIF
        RETURN -1;
    ENDFUNC

    FUNC num weighted_mean(num values{*},num weights{*})
        VAR num nSum:=0;
        VAR num nWeightSum:=0;
        FOR i FROM 1 TO Dim(values,1) DO
            nSum:=nSum+values{i}*weights{i};
            nWeightSum:=nWeightSum+weights{i};
        ENDFOR
        RETURN nSum/nWeightSum;
    ERROR
        TEST ERRNO
        CASE ERR_DIVZERO:
            RETURN 0;
        CASE ERR_OUTOFBND:
            ! weights shorter than values
            RETURN -1;
        DEFAULT:
            RAISE;
        ENDTEST
    ENDFUNC

    ! Samples with value 0 cannot be inverted: skip them with TRYNEXT
    PROC normalise_samples()
        FOR i FROM 1 TO Dim(nSamples,1) DO
            nIndex:=i;
            nSamples{i}:=100/nSamples{i};
        ENDFOR
        TPWrite "Samples skipped: "\Num:=nSkipped;
    ERROR
        IF ERRNO=ERR_DIVZERO THEN
            nSkipped:=nSkipped+1;
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    ! This handler is only entered for the listed errors;
    ! every other error propagates to the caller as usual.
    PROC read_sample_out_of_range()
        VAR num nValue;
        nIndex:=9;
        nValue:=nSamples{nIndex}/nDivisor;
        TPWrite "Value: "\Num:=nValue;
    ERROR (ERR_OUTOFBND,ERR_DIVZERO)
        IF ERRNO=ERR_OUTOFBND THEN
            nIndex:=Dim(nSamples,1);
            RETRY;
        ENDIF
        ! Division by zero: use a divisor of one and try again
        nDivisor:=1;
        RETRY;
    ENDPROC

    PROC retry_with_budget()
        VAR num nResult;
        nDivisor:=0;
        ResetRetryCount;
        nResult:=50/nDivisor;
        TPWrite "Result after retries: "\Num:=nResult;
    ERROR
        IF ERRNO=ERR_DIVZERO THEN
            TPWrite "Retries left: "\Num:=RemainingRetries();
            IF RemainingRetries()>1 THEN
                ! Simulate a sensor value that only arrives after a while
                nDivisor:=nDivisor+0.5;
                IF nDivisor<1 RETRY;
            ENDIF
            nDivisor:=2;
            RETRY;
        ELSEIF ERRNO=ERR_EXCRTYMAX THEN
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
