% Van Roy benchmark 'boyer', written for robocram from the benchmark's published
% description (Gabriel's "boyer": rewrite a formula to normal form with a table of
% lemmas, then prove it a tautology by case analysis on if/3). Not a copy of any
% distributed version: the lemma table here is our own set of valid identities, smaller
% than the original's, so figures compare with SWI on this program, not with published
% boyer times. The formula is the benchmark's published one. Entry point: top/0.

top :- boyer_wff(Wff), boyer_rewrite(Wff, Normal), boyer_taut(Normal, [], []).

boyer_wff(implies(and(implies(X, Y), and(implies(Y, Z), and(implies(Z, U), implies(U, W)))),
                  implies(X, W))) :-
    X = f(myplus(myplus(a, b), myplus(c, zero))),
    Y = f(times(times(a, b), myplus(c, d))),
    Z = f(reverse(append(append(a, b), []))),
    U = equal(myplus(a, b), difference(x, y)),
    W = lessp(remainder(a, b), member(a, length(b))).

boyer_rewrite(T, T) :- atomic(T), !.
boyer_rewrite(T, R) :-
    T =.. [F|Args], boyer_rewrite_args(Args, Args1), T1 =.. [F|Args1],
    ( boyer_lemma(T1, Rhs) -> boyer_rewrite(Rhs, R) ; R = T1 ).

boyer_rewrite_args([], []).
boyer_rewrite_args([A|As], [B|Bs]) :- boyer_rewrite(A, B), boyer_rewrite_args(As, Bs).

boyer_taut(t, _, _) :- !.
boyer_taut(W, Ts, _) :- boyer_in(W, Ts), !.
boyer_taut(W, _, Fs) :- boyer_in(W, Fs), !, fail.
boyer_taut(if(C, Then, Else), Ts, Fs) :- !,
    (   ( C == t ; boyer_in(C, Ts) ) -> boyer_taut(Then, Ts, Fs)
    ;   ( C == f ; boyer_in(C, Fs) ) -> boyer_taut(Else, Ts, Fs)
    ;   boyer_taut(Then, [C|Ts], Fs), boyer_taut(Else, Ts, [C|Fs])
    ).
boyer_taut(W, Ts, Fs) :- W \== f, \+ boyer_in(W, Fs), W = equal(A, A), \+ boyer_in(W, Ts).

boyer_in(X, [Y|Ys]) :- ( X == Y -> true ; boyer_in(X, Ys) ).

% propositional connectives to if/3
boyer_lemma(and(P, Q), if(P, if(Q, t, f), f)).
boyer_lemma(or(P, Q), if(P, t, if(Q, t, f))).
boyer_lemma(not(P), if(P, f, t)).
boyer_lemma(implies(P, Q), if(P, if(Q, t, f), t)).
boyer_lemma(iff(P, Q), and(implies(P, Q), implies(Q, P))).
% arithmetic on naturals
boyer_lemma(myplus(myplus(X, Y), Z), myplus(X, myplus(Y, Z))).
boyer_lemma(myplus(X, zero), fix(X)).
boyer_lemma(myplus(zero, X), fix(X)).
boyer_lemma(times(times(X, Y), Z), times(X, times(Y, Z))).
boyer_lemma(times(X, myplus(Y, Z)), myplus(times(X, Y), times(X, Z))).
boyer_lemma(times(X, one), fix(X)).
boyer_lemma(times(_, zero), zero).
boyer_lemma(difference(X, X), zero).
boyer_lemma(difference(myplus(X, Y), X), fix(Y)).
boyer_lemma(equal(myplus(A, B), zero), and(zerop(A), zerop(B))).
boyer_lemma(equal(myplus(A, B), myplus(A, C)), equal(fix(B), fix(C))).
boyer_lemma(equal(times(X, Y), zero), or(zerop(X), zerop(Y))).
boyer_lemma(equal(difference(X, Y), zero), not(lessp(Y, X))).
boyer_lemma(lessp(remainder(_, Y), Y), not(zerop(Y))).
boyer_lemma(lessp(X, X), f).
boyer_lemma(lessp(myplus(X, Y), myplus(X, Z)), lessp(Y, Z)).
boyer_lemma(remainder(_, one), zero).
boyer_lemma(remainder(X, X), zero).
boyer_lemma(zerop(X), or(equal(X, zero), not(numberp(X)))).
boyer_lemma(fix(X), if(numberp(X), X, zero)).
boyer_lemma(numberp(myplus(_, _)), t).
boyer_lemma(numberp(times(_, _)), t).
boyer_lemma(numberp(difference(_, _)), t).
boyer_lemma(numberp(remainder(_, _)), t).
boyer_lemma(numberp(length(_)), t).
boyer_lemma(numberp(zero), t).
% lists
boyer_lemma(append(append(X, Y), Z), append(X, append(Y, Z))).
boyer_lemma(append(X, []), X).
boyer_lemma(reverse(append(A, B)), append(reverse(B), reverse(A))).
boyer_lemma(reverse(reverse(X)), X).
boyer_lemma(length(reverse(X)), length(X)).
boyer_lemma(length(append(A, B)), myplus(length(A), length(B))).
boyer_lemma(member(X, append(A, B)), or(member(X, A), member(X, B))).
boyer_lemma(member(X, reverse(Y)), member(X, Y)).
boyer_lemma(member(X, [X|_]), t).
% equality
boyer_lemma(equal(X, X), t).
boyer_lemma(equal(t, f), f).
boyer_lemma(equal(f, t), f).
boyer_lemma(equal(append(A, B), append(A, C)), equal(B, C)).
boyer_lemma(equal(reverse(X), reverse(Y)), equal(X, Y)).
boyer_lemma(equal(if(A, B, C), D), if(A, equal(B, D), equal(C, D))).
boyer_lemma(if(if(A, B, C), D, E), if(A, if(B, D, E), if(C, D, E))).
boyer_lemma(if(t, X, _), X).
boyer_lemma(if(f, _, Y), Y).
boyer_lemma(if(_, Y, Y), Y).
